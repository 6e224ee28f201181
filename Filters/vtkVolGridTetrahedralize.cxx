#include "vtkVolGridTetrahedralize.h"

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointSet.h"
#include "vtkUnstructuredGrid.h"

vtkStandardNewMacro(vtkVolGridTetrahedralize);

vtkVolGridTetrahedralize::vtkVolGridTetrahedralize() = default;

int vtkVolGridTetrahedralize::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  return 1;
}

int vtkVolGridTetrahedralize::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  (void)inputVector;
  (void)outputVector;
  return 1;
}

void vtkVolGridTetrahedralize::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SpatialSort: " << this->SpatialSort << "\n";
  os << indent << "RandomSeed: " << this->RandomSeed << "\n";
  os << indent << "CheckOutput: " << this->CheckOutput << "\n";
}
