// An XML data parser that reads raw appended data whatever the expat version.
//
// Expat 2.6 (and Debian 12's libexpat1 from 2.5.0-1+deb12u2 on, CVE-2023-52425) defers re-parsing a
// token that arrives in small pieces. VTK 9.2's vtkXMLDataParser feeds the <AppendedData> tag to expat
// one character at a time and waits for its start-element callback before it reads the raw bytes;
// with deferral the callback comes too late and the binary block is parsed as XML ("not well-formed").
// This parser turns deferral off on each expat parser it creates, which restores the old behaviour.
#ifndef VolGridXMLDataParser_h
#define VolGridXMLDataParser_h

#include "vtkXMLDataParser.h"

class VolGridXMLDataParser : public vtkXMLDataParser
{
public:
  static VolGridXMLDataParser* New();
  vtkTypeMacro(VolGridXMLDataParser, vtkXMLDataParser);

  // True when the linked expat can defer re-parsing and offers the switch that turns it off.
  static bool ExpatHasReparseDeferral();

protected:
  VolGridXMLDataParser() = default;
  ~VolGridXMLDataParser() override = default;
  int CreateParser() override;

private:
  VolGridXMLDataParser(const VolGridXMLDataParser&) = delete;
  void operator=(const VolGridXMLDataParser&) = delete;
};

#endif
