#include "Regions.h"

#include "BoundaryCensus.h"

#include <algorithm>
#include <string>

namespace volgrid
{

const char* regionRuleName(RegionRule rule)
{
  switch (rule)
  {
    case RegionRule::EvenOdd:
      return "even-odd";
    case RegionRule::Orientation:
      return "orientation";
    case RegionRule::KeepAll:
      return "keep-all";
  }
  return "?";
}

static bool sameCyclicOrder(const int32_t* f, const int32_t* s)
{
  for (int r = 0; r < 3; ++r)
    if (f[0] == s[r] && f[1] == s[(r + 1) % 3] && f[2] == s[(r + 2) % 3])
      return true;
  return false;
}

namespace
{
// Bit i of mask[t] set when face i of tet t is a live boundary subface (both sides marked).
Status boundaryFaceMask(MeshEditor& ed, const BoundaryConstraints& bc, std::vector<uint8_t>& mask)
{
  const TetMesh& m = ed.mesh;
  BoundaryCensus census;
  census.take(ed, bc, /*withEdges=*/false);
  mask.assign(static_cast<size_t>(m.tetCapacity()), 0);
  for (int32_t f = 0; f < bc.capacity(); ++f)
  {
    if (!bc.alive(f))
      continue;
    const int32_t code = census.faceCode(f);
    const int32_t t = code < 0 ? -1 : code >> 2;
    const int i = code & 3;
    if (t < 0)
      return Status::failure(ErrorKind::InternalError,
                             "Exterior removal: boundary triangle " + std::to_string(bc.parent[f]) +
                               " is not a face of the mesh.",
                             { bc.parent[f] });
    mask[t] |= static_cast<uint8_t>(1u << i);
    const int32_t u = m.neighbor(t, i);
    if (u >= 0)
      mask[u] |= static_cast<uint8_t>(1u << m.mirrorFace(t, i));
  }
  return Status::success();
}

// Components of the tets across non-boundary faces, numbered in tet order into comp; returns their count.
// exterior: the component touching the hull (-1 if none).
int32_t labelComponents(const TetMesh& m, const std::vector<uint8_t>& mask, std::vector<int32_t>& comp,
                        int32_t& exterior)
{
  const int32_t cap = m.tetCapacity();
  comp.assign(static_cast<size_t>(cap), -1);
  std::vector<int32_t> queue;
  int32_t nc = 0;
  exterior = -1;
  for (int32_t s = 0; s < cap; ++s)
  {
    if (m.isFree(s) || comp[s] >= 0)
      continue;
    queue.assign(1, s);
    comp[s] = nc;
    for (size_t k = 0; k < queue.size(); ++k)
    {
      const int32_t t = queue[k];
      for (int i = 0; i < 4; ++i)
      {
        if (mask[t] & (1u << i))
          continue;
        const int32_t u = m.neighbor(t, i);
        if (u < 0)
          exterior = nc;
        else if (comp[u] < 0)
        {
          comp[u] = nc;
          queue.push_back(u);
        }
      }
    }
    ++nc;
  }
  return nc;
}

// Nesting depth of each component: boundary faces crossed from the exterior (-1 where unreachable).
std::vector<int32_t> componentDepths(const TetMesh& m, const std::vector<uint8_t>& mask,
                                     const std::vector<int32_t>& comp, int32_t nc, int32_t exterior)
{
  std::vector<std::vector<int32_t>> adj(static_cast<size_t>(nc));
  for (int32_t t = 0; t < m.tetCapacity(); ++t)
  {
    if (m.isFree(t) || !mask[t])
      continue;
    for (int i = 0; i < 4; ++i)
      if (mask[t] & (1u << i))
      {
        const int32_t u = m.neighbor(t, i);
        if (u >= 0 && comp[u] != comp[t])
          adj[comp[t]].push_back(comp[u]);
      }
  }
  for (auto& a : adj)
  {
    std::sort(a.begin(), a.end());
    a.erase(std::unique(a.begin(), a.end()), a.end());
  }
  std::vector<int32_t> depth(static_cast<size_t>(nc), -1), queue;
  if (exterior >= 0)
  {
    depth[exterior] = 0;
    queue.push_back(exterior);
  }
  for (size_t k = 0; k < queue.size(); ++k)
    for (int32_t c : adj[queue[k]])
      if (depth[c] < 0)
      {
        depth[c] = depth[queue[k]] + 1;
        queue.push_back(c);
      }
  return depth;
}

// The orientation rule: a component is kept when the facets around it point out of it; a failure when
// they point both ways.
Status keepByOrientation(const TetMesh& m, const BoundaryConstraints& bc, const std::vector<uint8_t>& mask,
                         const std::vector<int32_t>& comp, int32_t nc, int32_t exterior, std::vector<uint8_t>& keep)
{
  std::vector<int32_t> votesIn(static_cast<size_t>(nc), 0), votesOut(static_cast<size_t>(nc), 0);
  int32_t f[3];
  for (int32_t t = 0; t < m.tetCapacity(); ++t)
  {
    if (m.isFree(t) || !mask[t])
      continue;
    for (int i = 0; i < 4; ++i)
      if (mask[t] & (1u << i))
      {
        m.faceVertices(t, i, f);
        const int32_t sf = bc.findSubface(f[0], f[1], f[2]);
        // Same cyclic order: the tet lies on the side the facet normal points to (outside).
        if (sameCyclicOrder(f, bc.subface(sf)))
          ++votesOut[comp[t]];
        else
          ++votesIn[comp[t]];
      }
  }
  for (int32_t c = 0; c < nc; ++c)
  {
    if (c == exterior)
      continue;
    if (votesIn[c] > 0 && votesOut[c] > 0)
      return Status::failure(ErrorKind::InvalidOption,
                             "Region rule 'orientation': the facets around one region point both into and out of it (" +
                               std::to_string(votesIn[c]) + " and " + std::to_string(votesOut[c]) +
                               " faces); orient the input consistently or use the even-odd rule.");
    keep[c] = votesIn[c] > 0;
  }
  return Status::success();
}

// Labels the kept tets (res.tetRegion), unlinks them from the others and frees the others.
void deleteUnkept(TetMesh& m, const std::vector<int32_t>& comp, RegionResult& res)
{
  const int32_t cap = m.tetCapacity();
  res.tetRegion.assign(static_cast<size_t>(cap), -1);
  for (int32_t t = 0; t < cap; ++t)
  {
    if (m.isFree(t))
      continue;
    const int32_t r = res.componentRegion[comp[t]];
    if (r >= 0)
    {
      res.tetRegion[t] = r;
      continue;
    }
    for (int i = 0; i < 4; ++i)
    {
      const int32_t c = m.neighborCode(t, i);
      if (c >= 0 && res.componentRegion[comp[c >> 2]] >= 0)
        m.unlink(c >> 2, c & 3);
    }
  }
  for (int32_t t = 0; t < cap; ++t)
    if (!m.isFree(t) && res.tetRegion[t] < 0)
    {
      m.freeTet(t);
      ++res.removedTets;
    }
}
} // namespace

Status removeExterior(MeshEditor& ed, const BoundaryConstraints& bc, RegionRule rule, RegionResult& res,
                      Progress* progress)
{
  TetMesh& m = ed.mesh;
  SilentProgress silent;
  Progress* pr = progress ? progress : &silent;
  res = RegionResult();
  std::vector<uint8_t> mask;
  Status st = boundaryFaceMask(ed, bc, mask);
  if (!st.ok())
    return st;
  if (pr->cancelled())
    return Status::failure(ErrorKind::Cancelled, "Exterior removal was cancelled.");
  std::vector<int32_t> comp;
  int32_t exterior = -1;
  const int32_t nc = labelComponents(m, mask, comp, exterior);
  res.numComponents = nc;
  res.componentDepth = componentDepths(m, mask, comp, nc, exterior);
  // Keep.
  std::vector<uint8_t> keep(static_cast<size_t>(nc), 0);
  if (rule == RegionRule::Orientation)
  {
    st = keepByOrientation(m, bc, mask, comp, nc, exterior, keep);
    if (!st.ok())
      return st;
  }
  else
    for (int32_t c = 0; c < nc; ++c)
      keep[c] = c != exterior && (rule == RegionRule::KeepAll || (res.componentDepth[c] % 2) == 1);
  res.componentRegion.assign(static_cast<size_t>(nc), -1);
  for (int32_t c = 0; c < nc; ++c)
    if (keep[c])
      res.componentRegion[c] = res.numRegions++;
  if (res.numRegions == 0)
    return Status::failure(ErrorKind::InvalidOption,
                           std::string("No region of the domain is selected by the region rule '") +
                             regionRuleName(rule) +
                             "' (with the orientation rule, facet normals must point away from the domain).");
  deleteUnkept(m, comp, res);
  ed.rebuildVertexMap();
  return Status::success();
}

} // namespace volgrid
