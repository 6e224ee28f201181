/**
 * @class vtkVolGridMeshWriter
 * @brief Writes a tet grid in a solver format through VolGrid Core's writers (Core/IO/MeshWriter.h): gmsh
 * .msh, SU2, an OpenFOAM case, Medit .mesh, TetGen .node/.ele/.face, CGNS, Exodus II, with the named
 * boundary patches and regions. ParaView's File > Save Data and pvpython SaveData use it for those
 * extensions (Plugin/VolGridWriters.xml).
 *
 * The input is the volume output of VolGrid Tetrahedralize (or any tet grid carrying its
 * BoundaryFacePatch, Region, PatchNames and RegionNames arrays). The file is written atomically: a
 * failed write leaves no partial file and an earlier file untouched; the error names the path and reason.
 */
#ifndef vtkVolGridMeshWriter_h
#define vtkVolGridMeshWriter_h

#include "vtkVolGridFiltersModule.h" // for export macro
#include "vtkWriter.h"

#include <string>

class VTKVOLGRIDFILTERS_EXPORT vtkVolGridMeshWriter : public vtkWriter
{
public:
  static vtkVolGridMeshWriter* New();
  vtkTypeMacro(vtkVolGridMeshWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The output path. For OpenFOAM (format "openfoam", or the extension .foam) the case directory: a
  /// path ending in .foam names the directory without that extension, which must not exist yet.
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /// The format by name (gmsh, gmsh22, su2, openfoam, medit, tetgen, cgns, exodus); empty (default):
  /// by the file name's extension.
  vtkSetStringMacro(FormatName);
  vtkGetStringMacro(FormatName);
  ///@}

  /// The last write's error message ("" after a successful write).
  const std::string& GetLastError() const { return this->LastError; }

protected:
  vtkVolGridMeshWriter();
  ~vtkVolGridMeshWriter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  void WriteData() override;

private:
  vtkVolGridMeshWriter(const vtkVolGridMeshWriter&) = delete;
  void operator=(const vtkVolGridMeshWriter&) = delete;

  char* FileName = nullptr;
  char* FormatName = nullptr;
  std::string LastError;
};

#endif
