#include "vtkVolGridMeshWriter.h"

#include "VolGridSolverMeshFromGrid.h"

#include "vtkErrorCode.h"
#include "vtkInformation.h"
#include "vtkObjectFactory.h"
#include "vtkUnstructuredGrid.h"

#include "MeshWriter.h"
#include "SolverMesh.h"

vtkStandardNewMacro(vtkVolGridMeshWriter);

vtkVolGridMeshWriter::vtkVolGridMeshWriter() = default;

vtkVolGridMeshWriter::~vtkVolGridMeshWriter()
{
  this->SetFileName(nullptr);
  this->SetFormatName(nullptr);
}

int vtkVolGridMeshWriter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkUnstructuredGrid");
  return 1;
}

namespace
{
// The format and the path the Core writer takes: "CASE.foam" is the OpenFOAM case directory CASE.
volgrid::MeshFormat chooseFormat(const char* formatName, std::string& path)
{
  const bool foam = path.size() > 5 && path.compare(path.size() - 5, 5, ".foam") == 0;
  volgrid::MeshFormat format =
    formatName && *formatName ? volgrid::meshFormatFromName(formatName) : volgrid::meshFormatFromPath(path);
  if (foam && (format == volgrid::MeshFormat::Unknown || format == volgrid::MeshFormat::OpenFOAM))
  {
    path.resize(path.size() - 5);
    format = volgrid::MeshFormat::OpenFOAM;
  }
  return format;
}
} // namespace

void vtkVolGridMeshWriter::WriteData()
{
  this->LastError.clear();
  std::string path = this->FileName ? this->FileName : "";
  const volgrid::MeshFormat format = chooseFormat(this->FormatName, path);
  volgrid::SolverMesh mesh;
  if (path.empty())
    this->LastError = "no file name";
  else if (format == volgrid::MeshFormat::Unknown)
    this->LastError =
      "cannot tell the solver format of '" + path + "' (.msh .su2 .mesh .node .cgns .exo, .foam for an OpenFOAM case)";
  else if (!VolGridSolverMeshFromGrid(vtkUnstructuredGrid::SafeDownCast(this->GetInput()), mesh, this->LastError))
    this->LastError = "cannot write '" + path + "': " + this->LastError;
  else
  {
    volgrid::normalizeLabels(mesh);
    const volgrid::Status s = volgrid::writeSolverMesh(path, mesh, format);
    if (!s.ok())
      this->LastError = s.message;
  }
  if (!this->LastError.empty())
  {
    vtkErrorMacro(<< this->LastError);
    this->SetErrorCode(vtkErrorCode::CannotOpenFileError);
  }
}

void vtkVolGridMeshWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "FormatName: " << (this->FormatName ? this->FormatName : "(by extension)") << "\n";
}
