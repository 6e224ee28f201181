#include "vtkVolGridXMLUnstructuredGridReader.h"

#include "VolGridXMLDataParser.h"

#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkVolGridXMLUnstructuredGridReader);

void vtkVolGridXMLUnstructuredGridReader::CreateXMLParser()
{
  if (this->XMLParser)
  {
    this->DestroyXMLParser();
  }
  this->XMLParser = VolGridXMLDataParser::New();
}
