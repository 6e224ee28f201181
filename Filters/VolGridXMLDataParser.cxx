#include "VolGridXMLDataParser.h"

#include "vtkObjectFactory.h"

#include <dlfcn.h>

vtkStandardNewMacro(VolGridXMLDataParser);

namespace
{
// XML_Bool XML_SetReparseDeferralEnabled(XML_Parser, XML_Bool), looked up at run time: expat's headers
// are not part of VTK's SDK, and older expat libraries (which never defer) do not have the function.
using SetReparseDeferralEnabled = unsigned char (*)(void*, unsigned char);

SetReparseDeferralEnabled reparseDeferralSwitch()
{
  static const auto function =
    reinterpret_cast<SetReparseDeferralEnabled>(dlsym(RTLD_DEFAULT, "XML_SetReparseDeferralEnabled"));
  return function;
}
} // namespace

bool VolGridXMLDataParser::ExpatHasReparseDeferral()
{
  return reparseDeferralSwitch() != nullptr;
}

int VolGridXMLDataParser::CreateParser()
{
  const int created = this->Superclass::CreateParser();
  if (created && this->Parser)
  {
    if (SetReparseDeferralEnabled setEnabled = reparseDeferralSwitch())
    {
      setEnabled(this->Parser, 0);
    }
  }
  return created;
}
