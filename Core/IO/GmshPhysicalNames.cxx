#include "GmshPhysicalNames.h"

#include <string_view>
#include <vector>

namespace volgrid::detail
{
Status readGmshPhysicalNames(Scanner& sc, const std::function<void(int64_t dim, int64_t tag, std::string name)>& add)
{
  int64_t count = 0;
  Status s = sc.readCount(count, "the physical name count", 1 << 24);
  std::vector<std::string_view> toks;
  for (int64_t k = 0; k < count && s.ok(); ++k)
  {
    int64_t dim = 0, tag = 0;
    if (!sc.nextLine(toks) || toks.size() < 3 || !parseInt(toks[0], dim) || !parseInt(toks[1], tag))
      return sc.error("bad $PhysicalNames line");
    std::string name;
    for (size_t t = 2; t < toks.size(); ++t) // a quoted name may hold spaces
      name += (t > 2 ? " " : "") + std::string(toks[t]);
    if (name.size() >= 2 && name.front() == '"' && name.back() == '"')
      name = name.substr(1, name.size() - 2);
    add(dim, tag, std::move(name));
  }
  return s;
}
} // namespace volgrid::detail
