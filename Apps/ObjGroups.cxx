// OBJ `g` statements -> PatchId + PatchNames (see ObjGroups.h).
#include "ObjGroups.h"

#include "VolGridConversion.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPolyData.h"

#include <fstream>
#include <map>
#include <sstream>
#include <vector>

namespace volgrid
{

void objGroupsToPatches(const std::string& path, vtkPolyData* obj)
{
  vtkDataArray* groups = obj->GetCellData()->GetArray("GroupIds");
  if (!groups)
    return;
  std::vector<std::string> statements; // the name of each `g` statement, in file order
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line))
  {
    std::istringstream words(line);
    std::string keyword, word, name;
    if (!(words >> keyword) || keyword != "g")
      continue;
    while (words >> word)
      name += (name.empty() ? "" : " ") + word;
    statements.push_back(name.empty() ? "default" : name);
  }
  std::map<std::string, int32_t> patchOfName;
  std::map<int32_t, std::string> names;
  vtkNew<vtkIntArray> patch;
  patch->SetName("PatchId");
  patch->SetNumberOfValues(groups->GetNumberOfTuples());
  std::vector<int32_t> labels(static_cast<size_t>(groups->GetNumberOfTuples()));
  for (vtkIdType c = 0; c < groups->GetNumberOfTuples(); ++c)
  {
    const auto g = static_cast<size_t>(groups->GetTuple1(c));
    const std::string name = g < statements.size() ? statements[g] : "group" + std::to_string(g);
    const auto it = patchOfName.emplace(name, static_cast<int32_t>(patchOfName.size())).first;
    names[it->second] = name;
    labels[static_cast<size_t>(c)] = it->second;
    patch->SetValue(c, it->second);
  }
  obj->GetCellData()->RemoveArray("PatchId");
  obj->GetCellData()->AddArray(patch);
  VolGridSetLabelNames(obj, "PatchNames", labels, names, "patch");
}

} // namespace volgrid
