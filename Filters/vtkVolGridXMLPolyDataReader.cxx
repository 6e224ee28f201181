#include "vtkVolGridXMLPolyDataReader.h"

#include "VolGridXMLDataParser.h"

#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkVolGridXMLPolyDataReader);

void vtkVolGridXMLPolyDataReader::CreateXMLParser()
{
  if (this->XMLParser)
  {
    this->DestroyXMLParser();
  }
  this->XMLParser = VolGridXMLDataParser::New();
}
