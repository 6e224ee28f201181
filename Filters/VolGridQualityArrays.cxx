#include "VolGridQualityArrays.h"

#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkPoints.h"

vtkSmartPointer<vtkDoubleArray> VolGridNewCellArray(const char* name, vtkIdType n)
{
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName(name);
  a->SetNumberOfTuples(n);
  return a;
}

void VolGridAddScalar(vtkFieldData* fd, const char* name, double value)
{
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName(name);
  a->InsertNextValue(value);
  fd->AddArray(a);
}

const double* VolGridFlatPoints(vtkPoints* points, std::vector<double>& storage)
{
  vtkDataArray* data = points->GetData();
  if (auto* d = vtkDoubleArray::FastDownCast(data))
  {
    return d->GetPointer(0);
  }
  const vtkIdType n = points->GetNumberOfPoints();
  storage.resize(static_cast<size_t>(3 * n));
  vtkSMPTools::For(0, n,
                   [&](vtkIdType first, vtkIdType last)
                   {
                     for (vtkIdType i = first; i < last; ++i)
                     {
                       data->GetTuple(i, storage.data() + 3 * i);
                     }
                   });
  return storage.data();
}
