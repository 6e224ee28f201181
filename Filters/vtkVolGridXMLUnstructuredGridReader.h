/**
 * @class   vtkVolGridXMLUnstructuredGridReader
 * @brief   vtkXMLUnstructuredGridReader that also reads raw appended data on expat 2.6 and later.
 *
 * Identical to vtkXMLUnstructuredGridReader except for the XML parser, which turns off expat's reparse
 * deferral (see VolGridXMLDataParser.h). VTK 9.2's reader fails on files with raw appended data
 * (the default of VTK's and ParaView's XML writers) when the system expat defers, as Debian 12's
 * libexpat1 does since its CVE-2023-52425 update. VolGrid reads every .vtu through this class.
 */
#ifndef vtkVolGridXMLUnstructuredGridReader_h
#define vtkVolGridXMLUnstructuredGridReader_h

#include "vtkVolGridFiltersModule.h"
#include "vtkXMLUnstructuredGridReader.h"

class VTKVOLGRIDFILTERS_EXPORT vtkVolGridXMLUnstructuredGridReader : public vtkXMLUnstructuredGridReader
{
public:
  static vtkVolGridXMLUnstructuredGridReader* New();
  vtkTypeMacro(vtkVolGridXMLUnstructuredGridReader, vtkXMLUnstructuredGridReader);

protected:
  vtkVolGridXMLUnstructuredGridReader() = default;
  ~vtkVolGridXMLUnstructuredGridReader() override = default;
  void CreateXMLParser() override;

private:
  vtkVolGridXMLUnstructuredGridReader(const vtkVolGridXMLUnstructuredGridReader&) = delete;
  void operator=(const vtkVolGridXMLUnstructuredGridReader&) = delete;
};

#endif
