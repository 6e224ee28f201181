// Build-time generator: writes a Plugin XML from its template (.xml.in) with the defaults and slider
// ranges of Core/Base/OptionTable.h, so the ParaView panel cannot keep numbers of its own.
// usage: volgrid_generate_option_xml TEMPLATE OUTPUT
#include "AtomicFile.h"
#include "OptionTable.h"

#include <fstream>
#include <iostream>
#include <sstream>

int main(int argc, char** argv)
{
  if (argc != 3)
  {
    std::cerr << "usage: " << argv[0] << " TEMPLATE OUTPUT\n";
    return 2;
  }
  std::ifstream in(argv[1], std::ios::binary);
  if (!in)
  {
    std::cerr << argv[0] << ": cannot read " << argv[1] << "\n";
    return 1;
  }
  std::ostringstream text;
  text << in.rdbuf();
  std::string filled;
  const volgrid::Status status = volgrid::fillOptionPlaceholders(text.str(), filled);
  if (!status.ok())
  {
    std::cerr << argv[1] << ": " << status.message << "\n";
    return 1;
  }
  std::string error;
  if (!volgrid::writeFileAtomically(argv[2], filled, error))
  {
    std::cerr << argv[0] << ": " << error << "\n";
    return 1;
  }
  return 0;
}
