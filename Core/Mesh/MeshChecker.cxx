#include "MeshChecker.h"

#include "Predicates.h"

#include <algorithm>
#include <sstream>

namespace volgrid
{
namespace
{

uint64_t pairKey(int32_t a, int32_t b) // directed pair, a and b may be kGhostVertex
{
  return (uint64_t(static_cast<uint32_t>(a + 1)) << 32) | static_cast<uint32_t>(b + 1);
}

// Same three vertices, opposite cyclic orientation.
bool oppositeFaces(const int32_t f[3], const int32_t g[3])
{
  for (int r = 0; r < 3; ++r)
    if (f[0] == g[r] && f[1] == g[(r + 2) % 3] && f[2] == g[(r + 1) % 3])
      return true;
  return false;
}

struct Checker
{
  const TetMesh& mesh;
  const MeshCheckOptions& opt;
  MeshCheckReport& rep;

  void bad(int64_t& counter, int32_t t)
  {
    ++counter;
    rep.valid = false;
    if (rep.firstBadTets.size() < opt.maxReported &&
        std::find(rep.firstBadTets.begin(), rep.firstBadTets.end(), t) == rep.firstBadTets.end())
      rep.firstBadTets.push_back(t);
  }

  const double* P(int32_t v) const { return mesh.point(v); }

  // The mesher's conflict rule: is vertex x in conflict with (finite or ghost) tet t?
  bool inConflict(int32_t t, int32_t x) const
  {
    const int32_t* w = mesh.vertices(t);
    const int k = mesh.ghostIndex(t);
    if (k >= 0)
    {
      int32_t f[3];
      mesh.faceVertices(t, k, f);
      const int o = predicates::orient3d(P(f[0]), P(f[1]), P(f[2]), P(x));
      if (o != 0)
        return o > 0;
      const int32_t u = mesh.neighbor(t, k);
      if (u < 0 || mesh.isGhost(u))
        return false; // reported elsewhere
      w = mesh.vertices(u);
    }
    return predicates::insphereSoS(P(w[0]), P(w[1]), P(w[2]), P(w[3]), P(x), w[0], w[1], w[2], w[3], x) > 0;
  }

  void run()
  {
    const int32_t cap = mesh.tetCapacity();
    const int32_t nv = mesh.numVertices();
    std::vector<uint8_t> okVerts(static_cast<size_t>(cap), 0);
    bool anyGhost = false;
    // Vertices and orientation.
    for (int32_t t = 0; t < cap; ++t)
    {
      if (mesh.isFree(t))
        continue;
      const int32_t* w = mesh.vertices(t);
      int ghosts = 0;
      bool ok = true;
      for (int i = 0; i < 4; ++i)
      {
        if (w[i] == TetMesh::kGhostVertex)
          ++ghosts;
        else if (w[i] < 0 || w[i] >= nv)
          ok = false;
        for (int j = 0; j < i; ++j)
          ok = ok && w[i] != w[j];
      }
      if (!ok || ghosts > 1)
      {
        bad(rep.badVertices, t);
        continue;
      }
      okVerts[t] = 1;
      if (ghosts)
      {
        anyGhost = true;
        ++rep.ghostTets;
        continue;
      }
      ++rep.finiteTets;
      if (predicates::orient3d(P(w[0]), P(w[1]), P(w[2]), P(w[3])) <= 0)
        bad(rep.invertedTets, t);
    }
    // Adjacency, hull faces, local Delaunay.
    std::vector<uint64_t> hullEdges; // directed edges of hull faces oriented outwards
    for (int32_t t = 0; t < cap; ++t)
    {
      if (mesh.isFree(t) || !okVerts[t])
        continue;
      const bool tGhost = mesh.isGhost(t);
      const int k = tGhost ? mesh.ghostIndex(t) : -1;
      for (int i = 0; i < 4; ++i)
      {
        int32_t f[3];
        mesh.faceVertices(t, i, f);
        const int32_t code = mesh.neighborCode(t, i);
        if (code < 0)
        {
          if (anyGhost || tGhost)
            bad(rep.openFaces, t);
          else
          {
            ++rep.hullFaces;
            // Seen from outside: reversed.
            hullEdges.push_back(pairKey(f[0], f[2]));
            hullEdges.push_back(pairKey(f[2], f[1]));
            hullEdges.push_back(pairKey(f[1], f[0]));
          }
          continue;
        }
        const int32_t u = code >> 2;
        const int j = code & 3;
        if (u >= cap || mesh.isFree(u))
        {
          bad(rep.badNeighbors, t);
          continue;
        }
        if (mesh.neighborCode(u, j) != TetMesh::encode(t, i))
        {
          bad(rep.asymmetricNeighbors, t);
          continue;
        }
        if (!okVerts[u])
          continue;
        int32_t g[3];
        mesh.faceVertices(u, j, g);
        if (!oppositeFaces(f, g))
        {
          bad(rep.faceMismatches, t);
          continue;
        }
        const bool uGhost = mesh.isGhost(u);
        if (tGhost && i == k)
        {
          // The hull face of a ghost must lie on a finite tet.
          if (uGhost)
            bad(rep.hullErrors, t);
          else
          {
            ++rep.hullFaces;
            hullEdges.push_back(pairKey(f[0], f[1]));
            hullEdges.push_back(pairKey(f[1], f[2]));
            hullEdges.push_back(pairKey(f[2], f[0]));
          }
          continue;
        }
        if (!opt.delaunay || u < t)
          continue;
        const int32_t x = mesh.vertex(u, j); // vertex of u opposite the shared face
        if (!tGhost && !uGhost)
        {
          if (inConflict(t, x))
            bad(rep.nonDelaunayFaces, t);
        }
        else if (tGhost && uGhost)
        {
          // Hull edge shared by the hull faces of t and u: convex (and SoS-Delaunay if flat).
          if (inConflict(t, x) || inConflict(u, mesh.vertex(t, i)))
            bad(rep.nonConvexHullEdges, t);
        }
      }
    }
    // Hull: closed, consistently oriented 2-manifold with Euler characteristic 2.
    if (rep.hullFaces > 0)
    {
      std::sort(hullEdges.begin(), hullEdges.end());
      int64_t errors = 0;
      for (size_t e = 0; e < hullEdges.size(); ++e)
      {
        if (e + 1 < hullEdges.size() && hullEdges[e + 1] == hullEdges[e])
          ++errors; // directed edge used twice
        const uint64_t rev = (hullEdges[e] << 32) | (hullEdges[e] >> 32);
        if (!std::binary_search(hullEdges.begin(), hullEdges.end(), rev))
          ++errors; // open edge
      }
      std::vector<int32_t> hv;
      hv.reserve(hullEdges.size());
      for (uint64_t e : hullEdges)
        hv.push_back(static_cast<int32_t>(e >> 32) - 1);
      std::sort(hv.begin(), hv.end());
      const int64_t hullVerts = std::unique(hv.begin(), hv.end()) - hv.begin();
      const int64_t chi = hullVerts - static_cast<int64_t>(hullEdges.size()) / 2 + rep.hullFaces;
      if (chi != 2)
        ++errors;
      if (errors)
      {
        rep.hullErrors += errors;
        rep.valid = false;
      }
    }
    if (opt.euler)
      euler();
  }

  void euler()
  {
    std::vector<uint64_t> edges;
    std::vector<int32_t> verts;
    edges.reserve(6 * static_cast<size_t>(rep.finiteTets));
    verts.reserve(4 * static_cast<size_t>(rep.finiteTets));
    mesh.forEachFiniteTet(
      [&](int32_t t)
      {
        const int32_t* w = mesh.vertices(t);
        for (int i = 0; i < 4; ++i)
        {
          verts.push_back(w[i]);
          for (int j = i + 1; j < 4; ++j)
            edges.push_back(pairKey(std::min(w[i], w[j]), std::max(w[i], w[j])));
        }
      });
    std::sort(edges.begin(), edges.end());
    rep.edges = std::unique(edges.begin(), edges.end()) - edges.begin();
    std::sort(verts.begin(), verts.end());
    rep.vertices = std::unique(verts.begin(), verts.end()) - verts.begin();
    const int64_t faces = (4 * rep.finiteTets + rep.hullFaces) / 2;
    if (rep.finiteTets > 0 && rep.vertices - rep.edges + faces - rep.finiteTets != 1)
    {
      rep.eulerOk = false;
      rep.valid = false;
    }
  }
};

} // namespace

std::string MeshCheckReport::summary() const
{
  std::ostringstream s;
  s << (valid ? "valid" : "INVALID") << ": " << finiteTets << " finite tets, " << ghostTets << " ghost tets, "
    << hullFaces << " hull faces";
  if (edges)
    s << ", " << vertices << " vertices, " << edges << " edges";
  auto item = [&](int64_t n, const char* what)
  {
    if (n)
      s << "; " << n << " " << what;
  };
  item(badVertices, "bad vertex tuples");
  item(invertedTets, "inverted/flat tets");
  item(badNeighbors, "bad neighbour refs");
  item(asymmetricNeighbors, "asymmetric neighbours");
  item(faceMismatches, "shared-face mismatches");
  item(openFaces, "faces without neighbour");
  item(hullErrors, "hull errors");
  item(nonDelaunayFaces, "non-Delaunay faces");
  item(nonConvexHullEdges, "non-convex hull edges");
  if (!eulerOk)
    s << "; Euler characteristic != 1";
  if (!firstBadTets.empty())
  {
    s << "; first tets:";
    for (int32_t t : firstBadTets)
      s << " " << t;
  }
  return s.str();
}

MeshCheckReport checkMesh(const TetMesh& mesh, const MeshCheckOptions& options)
{
  MeshCheckReport rep;
  Checker c{ mesh, options, rep };
  c.run();
  return rep;
}

} // namespace volgrid
