/**
 * @class   vtkVolGridXMLPolyDataReader
 * @brief   vtkXMLPolyDataReader that also reads raw appended data on expat 2.6 and later.
 *
 * Identical to vtkXMLPolyDataReader except for the XML parser, which turns off expat's reparse
 * deferral (see VolGridXMLDataParser.h). VTK 9.2's reader fails on files with raw appended data
 * (the default of VTK's and ParaView's XML writers) when the system expat defers, as Debian 12's
 * libexpat1 does since its CVE-2023-52425 update. VolGrid reads every .vtp through this class.
 */
#ifndef vtkVolGridXMLPolyDataReader_h
#define vtkVolGridXMLPolyDataReader_h

#include "vtkVolGridFiltersModule.h"
#include "vtkXMLPolyDataReader.h"

class VTKVOLGRIDFILTERS_EXPORT vtkVolGridXMLPolyDataReader : public vtkXMLPolyDataReader
{
public:
  static vtkVolGridXMLPolyDataReader* New();
  vtkTypeMacro(vtkVolGridXMLPolyDataReader, vtkXMLPolyDataReader);

protected:
  vtkVolGridXMLPolyDataReader() = default;
  ~vtkVolGridXMLPolyDataReader() override = default;
  void CreateXMLParser() override;

private:
  vtkVolGridXMLPolyDataReader(const vtkVolGridXMLPolyDataReader&) = delete;
  void operator=(const vtkVolGridXMLPolyDataReader&) = delete;
};

#endif
