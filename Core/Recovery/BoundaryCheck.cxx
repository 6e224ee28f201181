#include "BoundaryCheck.h"

#include "BoundaryRecovery.h"
#include "ParallelFor.h"
#include "Predicates.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <unordered_map>

namespace volgrid
{

namespace
{

// Neumaier summation.
struct Sum
{
  double s = 0, c = 0;
  void add(double x)
  {
    const double t = s + x;
    if (std::fabs(s) >= std::fabs(x))
      c += (s - t) + x;
    else
      c += (x - t) + s;
    s = t;
  }
  double value() const { return s + c; }
};

double det3(const double* a, const double* b, const double* c, const double* d)
{
  const double e0[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
  const double e1[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
  const double e2[3] = { d[0] - a[0], d[1] - a[1], d[2] - a[2] };
  return e0[0] * (e1[1] * e2[2] - e1[2] * e2[1]) - e0[1] * (e1[0] * e2[2] - e1[2] * e2[0]) +
    e0[2] * (e1[0] * e2[1] - e1[1] * e2[0]);
}

} // namespace

std::string BoundaryCheckReport::summary() const
{
  std::ostringstream os;
  os << tets << " tets";
  if (invertedTets)
    os << ", " << invertedTets << " inverted";
  if (badIds)
    os << ", " << badIds << " with bad ids";
  if (overSharedFaces)
    os << ", " << overSharedFaces << " faces in >2 tets";
  if (sameOrientationFaces)
    os << ", " << sameOrientationFaces << " badly oriented shared faces";
  os << "; " << boundaryFaces << " boundary faces";
  if (boundaryFacesNotInput)
    os << ", " << boundaryFacesNotInput << " not input triangles";
  if (inputTrianglesNotFaces)
    os << ", " << inputTrianglesNotFaces << " input triangles missing";
  if (boundaryPointsAdded)
    os << ", " << boundaryPointsAdded << " added points on the boundary";
  if (inputTrianglesInterior)
    os << ", " << inputTrianglesInterior << " interface triangles";
  os.precision(12);
  os << "; volume " << tetVolume << " vs " << enclosedVolume << " (rel. error " << relativeVolumeError << ")";
  os << (ok() ? " OK" : " FAILED");
  return os.str();
}

namespace
{
using InputTriangles = std::unordered_map<TriKey, int32_t, TriKeyHash>;

// Face code & 3 of tet code >> 2, as vertex ids.
void faceOf(const std::vector<int32_t>& tets, uint32_t code, int32_t f[3])
{
  const int32_t* v = tets.data() + 4 * static_cast<int64_t>(code >> 2);
  const int* fv = TetMesh::kFaceVertex[code & 3];
  f[0] = v[fv[0]];
  f[1] = v[fv[1]];
  f[2] = v[fv[2]];
}

size_t smallestVertex(const int32_t f[3])
{
  return static_cast<size_t>(std::min({ f[0], f[1], f[2] }));
}

// Tets checked per block: the blocks' volume sums are added in block order, so the total does not depend
// on how many threads share the blocks.
constexpr int64_t kTetsPerBlock = 65536;

// The ids and the orientation of tets [begin, end) (problems noted as 8 * tet in events), their volume, and
// valid[t] = 1 for those with valid ids.
void scanTetRange(const std::vector<double>& points, const std::vector<int32_t>& tets, int64_t begin, int64_t end,
                  std::vector<uint8_t>& valid, Sum& vol, int64_t& badIds, int64_t& inverted,
                  std::vector<int64_t>& events)
{
  const int64_t np = static_cast<int64_t>(points.size() / 3);
  for (int64_t t = begin; t < end; ++t)
  {
    const int32_t* v = tets.data() + 4 * t;
    bool bad = false;
    for (int i = 0; i < 4; ++i)
    {
      if (v[i] < 0 || v[i] >= np)
        bad = true;
      for (int j = i + 1; j < 4; ++j)
        bad = bad || v[i] == v[j];
    }
    if (bad)
    {
      ++badIds;
      events.push_back(8 * t);
      continue;
    }
    valid[static_cast<size_t>(t)] = 1;
    const double *a = &points[3 * static_cast<size_t>(v[0])], *b = &points[3 * static_cast<size_t>(v[1])],
                 *c = &points[3 * static_cast<size_t>(v[2])], *d = &points[3 * static_cast<size_t>(v[3])];
    if (predicates::orient3d(a, b, c, d) <= 0)
    {
      ++inverted;
      events.push_back(8 * t);
    }
    vol.add(det3(a, b, c, d) / 6.0);
  }
}

// The tet loop: ids and orientation (problems noted as 8 * tet in events, in tet order), the volume,
// valid[t] = 1 for tets with valid ids, and the faces of those counted per smallest vertex v in start[v + 1].
// Blocks of tets on `threads` threads (ParallelFor.h's rule); the report is the same for any count.
void scanTets(const std::vector<double>& points, const std::vector<int32_t>& tets, int threads, BoundaryCheckReport& r,
              std::vector<uint8_t>& valid, std::vector<int64_t>& start, std::vector<int64_t>& events)
{
  const int64_t np = static_cast<int64_t>(points.size() / 3);
  const int64_t nt = static_cast<int64_t>(tets.size() / 4);
  valid.assign(static_cast<size_t>(nt), 0);
  const int64_t blocks = (nt + kTetsPerBlock - 1) / kTetsPerBlock;
  struct Block
  {
    Sum vol;
    int64_t badIds = 0, inverted = 0;
    std::vector<int64_t> events;
  };
  std::vector<Block> block(static_cast<size_t>(blocks));
  parallelFor(threads, blocks, 1,
              [&](int, int64_t first, int64_t last)
              {
                for (int64_t k = first; k < last; ++k)
                {
                  Block& b = block[static_cast<size_t>(k)];
                  scanTetRange(points, tets, k * kTetsPerBlock, std::min(nt, (k + 1) * kTetsPerBlock), valid, b.vol,
                               b.badIds, b.inverted, b.events);
                }
              });
  Sum vol;
  for (const Block& b : block)
  {
    vol.add(b.vol.s);
    vol.add(b.vol.c);
    r.badIds += b.badIds;
    r.invertedTets += b.inverted;
    events.insert(events.end(), b.events.begin(), b.events.end());
  }
  r.tetVolume = vol.value();
  start.assign(static_cast<size_t>(np) + 1, 0);
  for (int64_t t = 0; t < nt; ++t)
    if (valid[static_cast<size_t>(t)])
      for (int i = 0; i < 4; ++i)
      {
        int32_t f[3];
        faceOf(tets, static_cast<uint32_t>(4 * t + i), f);
        ++start[smallestVertex(f) + 1];
      }
}

// The face codes (4 * tet + face) of the valid tets bucketed by smallest vertex, in tet order within a
// bucket; start (the counts) becomes the buckets' offsets.
std::vector<uint32_t> bucketFaces(const std::vector<int32_t>& tets, const std::vector<uint8_t>& valid,
                                  std::vector<int64_t>& start)
{
  const size_t np = start.size() - 1;
  for (size_t v = 0; v < np; ++v)
    start[v + 1] += start[v];
  std::vector<uint32_t> codes(static_cast<size_t>(start[np]));
  std::vector<int64_t> next(start.begin(), start.end() - 1);
  for (size_t t = 0; t < valid.size(); ++t)
    if (valid[t])
      for (int i = 0; i < 4; ++i)
      {
        int32_t f[3];
        faceOf(tets, static_cast<uint32_t>(4 * t + i), f);
        codes[static_cast<size_t>(next[smallestVertex(f)]++)] = static_cast<uint32_t>(4 * t + i);
      }
  return codes;
}

// What matching the faces finds besides the report's counts: for the whole check, and per range of
// smallest vertices (the ranges are matched on threads and joined in order).
struct FaceMatch
{
  std::vector<int32_t> uses;       // per input triangle: tets having it as a face (0 missing, at most 3)
  std::vector<uint8_t> onBoundary; // per point: on a face of a single tet
  std::vector<uint8_t> onInput;    // per point: a vertex of an input triangle (other faces need no look-up)
  bool listSharedFaces = false;    // whether the caller wants RangeMatch::sharedFaces
};
struct RangeMatch
{
  int64_t sameOrientationFaces = 0, overSharedFaces = 0, boundaryFaces = 0, boundaryFacesNotInput = 0;
  std::vector<int64_t> events;                          // as the check's events
  std::vector<int64_t> boundaryNotes;                   // tets with a boundary face that is not an input triangle
  std::vector<int32_t> boundaryPoints;                  // the vertices of the boundary faces (repeated)
  std::vector<std::pair<int32_t, int32_t>> sharedFaces; // the tets of each face that two tets share
};

// A face in its bucket: the other two vertices (sorted) as one key, its code, and the parity of the
// permutation that sorts its three vertices as its tet lists them. Two listings of the same three distinct
// vertices are cyclic rotations of each other exactly when their parities agree, so the orientation test
// needs no second look at the tets.
struct BucketFace
{
  uint64_t key;
  uint32_t code;
  uint8_t parity;
  bool operator<(const BucketFace& o) const { return key != o.key ? key < o.key : code < o.code; }
};

BucketFace bucketFace(const std::vector<int32_t>& tets, uint32_t code)
{
  int32_t f[3];
  faceOf(tets, code, f);
  const int inversions = (f[0] > f[1]) + (f[0] > f[2]) + (f[1] > f[2]);
  std::sort(f, f + 3);
  return { (static_cast<uint64_t>(static_cast<uint32_t>(f[1])) << 32) | static_cast<uint32_t>(f[2]), code,
           static_cast<uint8_t>(inversions & 1) };
}

// Groups the faces of the buckets [first, last) (equal faces together, in tet order) and counts badly
// oriented and over-shared faces (noted in events), boundary faces and the input triangles' uses
// (m.uses: each triangle is written by the range of its smallest vertex only).
void matchFaces(const std::vector<int32_t>& tets, const std::vector<int64_t>& start, const std::vector<uint32_t>& codes,
                const InputTriangles& input, size_t first, size_t last, FaceMatch& m, RangeMatch& r)
{
  std::vector<BucketFace> group;
  for (size_t v = first; v < last; ++v)
  {
    group.clear();
    for (int64_t k = start[v]; k < start[v + 1]; ++k)
      group.push_back(bucketFace(tets, codes[static_cast<size_t>(k)]));
    std::sort(group.begin(), group.end()); // equal faces together, in tet order (as first seen)
    for (size_t k = 0; k < group.size();)
    {
      size_t e = k + 1;
      while (e < group.size() && group[e].key == group[k].key)
        ++e;
      const int64_t count = static_cast<int64_t>(e - k);
      if (count >= 2 && group[k + 1].parity == group[k].parity)
      {
        ++r.sameOrientationFaces;
        r.events.push_back(8 * static_cast<int64_t>(group[k + 1].code >> 2) + 1 + (group[k + 1].code & 3));
      }
      if (count == 2 && m.listSharedFaces)
        r.sharedFaces.push_back(
          { static_cast<int32_t>(group[k].code >> 2), static_cast<int32_t>(group[k + 1].code >> 2) });
      if (count >= 3)
      {
        ++r.overSharedFaces;
        r.events.push_back(8 * static_cast<int64_t>(group[k + 2].code >> 2) + 1 + (group[k + 2].code & 3));
      }
      const int32_t b = static_cast<int32_t>(group[k].key >> 32), c = static_cast<int32_t>(group[k].key & 0xffffffffu);
      const bool maybeInput = m.onInput[v] && m.onInput[static_cast<size_t>(b)] && m.onInput[static_cast<size_t>(c)];
      const auto it = maybeInput ? input.find(TriKey(static_cast<int32_t>(v), b, c)) : input.end();
      if (it != input.end())
        m.uses[static_cast<size_t>(it->second)] = static_cast<int32_t>(std::min<int64_t>(count, 3));
      if (count == 1)
      {
        ++r.boundaryFaces;
        if (it == input.end())
        {
          ++r.boundaryFacesNotInput;
          r.boundaryNotes.push_back(group[k].code >> 2);
        }
        r.boundaryPoints.insert(r.boundaryPoints.end(), { static_cast<int32_t>(v), b, c });
      }
      k = e;
    }
  }
}

// matchFaces over every bucket, in ranges of vertices on `threads` threads, joined in range order (the
// report and the lists are those of one range). events and boundaryNotes are appended to; sharedFaces
// (optional) receives the shared faces.
void matchAllFaces(const std::vector<int32_t>& tets, const std::vector<int64_t>& start,
                   const std::vector<uint32_t>& codes, const InputTriangles& input, int threads, FaceMatch& m,
                   BoundaryCheckReport& r, std::vector<int64_t>& events, std::vector<int64_t>& boundaryNotes,
                   std::vector<std::pair<int32_t, int32_t>>* sharedFaces)
{
  const int64_t np = static_cast<int64_t>(start.size()) - 1;
  constexpr int64_t kMinVerticesPerThread = 16384;
  m.listSharedFaces = sharedFaces != nullptr;
  std::vector<RangeMatch> ranges(static_cast<size_t>(parallelRanges(threads, np, kMinVerticesPerThread)));
  parallelFor(threads, np, kMinVerticesPerThread,
              [&](int k, int64_t first, int64_t last)
              {
                matchFaces(tets, start, codes, input, static_cast<size_t>(first), static_cast<size_t>(last), m,
                           ranges[static_cast<size_t>(k)]);
              });
  if (sharedFaces)
    sharedFaces->clear();
  for (RangeMatch& range : ranges)
  {
    r.sameOrientationFaces += range.sameOrientationFaces;
    r.overSharedFaces += range.overSharedFaces;
    r.boundaryFaces += range.boundaryFaces;
    r.boundaryFacesNotInput += range.boundaryFacesNotInput;
    events.insert(events.end(), range.events.begin(), range.events.end());
    boundaryNotes.insert(boundaryNotes.end(), range.boundaryNotes.begin(), range.boundaryNotes.end());
    for (int32_t v : range.boundaryPoints)
      m.onBoundary[static_cast<size_t>(v)] = 1;
    if (sharedFaces)
      sharedFaces->insert(sharedFaces->end(), range.sharedFaces.begin(), range.sharedFaces.end());
    range = RangeMatch(); // its memory goes before the next range's is copied
  }
}
} // namespace

BoundaryCheckReport checkBoundaryConformity(const std::vector<double>& points, int32_t numInputPoints,
                                            const std::vector<int32_t>& tets, const std::vector<int32_t>& triangles,
                                            double expected, std::vector<std::pair<int32_t, int32_t>>* sharedFaces,
                                            int threads)
{
  BoundaryCheckReport r;
  const int64_t np = static_cast<int64_t>(points.size() / 3);
  r.tets = static_cast<int64_t>(tets.size() / 4);
  // Tets with valid ids: orientation and volume; their faces are then matched by a counting sort on the
  // smallest vertex (4 bytes per face and 8 per vertex; a hash table of faces took about 150 bytes per tet,
  // the CLI's peak at a million tets). Face codes are 4 * tet + face in 32 bits (TetMesh's own limit is
  // lower: 2^29 tets).
  std::vector<uint8_t> valid;
  std::vector<int64_t> events; // 8 * tet + slot (0 bad or inverted, 1 + face): notes in tet order
  std::vector<int64_t> start;
  scanTets(points, tets, threads, r, valid, start, events);
  r.enclosedVolume = expected;
  r.relativeVolumeError = std::fabs(r.tetVolume - expected) / std::max(std::fabs(expected), 1e-300);
  const std::vector<uint32_t> codes = bucketFaces(tets, valid, start);
  std::vector<uint8_t>().swap(valid);
  // Input triangles by key; per triangle, how many tets use it as a face (0 = missing).
  InputTriangles input;
  const int64_t ntri = static_cast<int64_t>(triangles.size() / 3);
  input.reserve(static_cast<size_t>(ntri) * 2 + 16);
  for (int64_t t = 0; t < ntri; ++t)
    input.emplace(TriKey(triangles[3 * t], triangles[3 * t + 1], triangles[3 * t + 2]), static_cast<int32_t>(t));
  FaceMatch m;
  m.uses.assign(static_cast<size_t>(ntri), 0);
  m.onBoundary.assign(static_cast<size_t>(np), 0);
  m.onInput.assign(static_cast<size_t>(np), 0);
  for (int32_t v : triangles)
    if (v >= 0 && v < np)
      m.onInput[static_cast<size_t>(v)] = 1;
  std::vector<int64_t> boundaryNotes;
  matchAllFaces(tets, start, codes, input, threads, m, r, events, boundaryNotes, sharedFaces);
  // The first problems: the tet loop's (in tet order), then the boundary's, then the input's.
  std::sort(events.begin(), events.end());
  for (size_t k = 0; k < events.size() && r.firstProblems.size() < 8; ++k)
    r.firstProblems.push_back(events[k] / 8);
  for (size_t k = 0; k < boundaryNotes.size() && r.firstProblems.size() < 8; ++k)
    r.firstProblems.push_back(boundaryNotes[k]);
  for (int64_t v = numInputPoints; v < np; ++v)
    r.boundaryPointsAdded += m.onBoundary[static_cast<size_t>(v)];
  for (int64_t t = 0; t < ntri; ++t)
  {
    const auto it = input.find(TriKey(triangles[3 * t], triangles[3 * t + 1], triangles[3 * t + 2]));
    if (it->second != t)
      continue; // a repeated input triangle: counted once
    if (m.uses[static_cast<size_t>(t)] == 0)
    {
      ++r.inputTrianglesNotFaces;
      if (r.firstProblems.size() < 8)
        r.firstProblems.push_back(t);
    }
    else if (m.uses[static_cast<size_t>(t)] == 2)
      ++r.inputTrianglesInterior;
  }
  return r;
}

double enclosedVolume(const std::vector<double>& points, const std::vector<int32_t>& triangles,
                      const std::vector<int32_t>& triangleShell, const std::vector<int>& shellDepth, RegionRule rule)
{
  const int32_t nt = static_cast<int32_t>(triangles.size() / 3);
  // Reference point: the box centre (reduces cancellation).
  double lo[3] = { 1e300, 1e300, 1e300 }, hi[3] = { -1e300, -1e300, -1e300 };
  for (int32_t t = 0; t < 3 * nt; ++t)
    for (int k = 0; k < 3; ++k)
    {
      lo[k] = std::min(lo[k], points[3 * static_cast<size_t>(triangles[t]) + k]);
      hi[k] = std::max(hi[k], points[3 * static_cast<size_t>(triangles[t]) + k]);
    }
  const double c[3] = { 0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]), 0.5 * (lo[2] + hi[2]) };
  auto tri = [&](int32_t t, int k) { return &points[3 * static_cast<size_t>(triangles[3 * t + k])]; };
  if (rule == RegionRule::Orientation)
  {
    Sum s;
    for (int32_t t = 0; t < nt; ++t)
      s.add(det3(c, tri(t, 0), tri(t, 1), tri(t, 2)) / 6.0);
    return s.value();
  }
  // Orient every shell consistently by propagation across shared edges.
  std::unordered_map<uint64_t, std::vector<int32_t>> edgeTris;
  edgeTris.reserve(static_cast<size_t>(nt) * 2);
  for (int32_t t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k)
      edgeTris[edgeKey(triangles[3 * t + k], triangles[3 * t + (k + 1) % 3])].push_back(t);
  std::vector<int8_t> flip(static_cast<size_t>(nt), -1);
  int32_t nshell = 0;
  for (int32_t s : triangleShell)
    nshell = std::max(nshell, s + 1);
  std::vector<Sum> shellVol(static_cast<size_t>(nshell));
  std::vector<int32_t> queue;
  for (int32_t s0 = 0; s0 < nt; ++s0)
  {
    if (flip[s0] >= 0)
      continue;
    flip[s0] = 0;
    queue.assign(1, s0);
    for (size_t q = 0; q < queue.size(); ++q)
    {
      const int32_t t = queue[q];
      for (int k = 0; k < 3; ++k)
      {
        int32_t a = triangles[3 * t + k], b = triangles[3 * t + (k + 1) % 3];
        if (flip[t])
          std::swap(a, b);
        for (int32_t u : edgeTris[edgeKey(a, b)])
        {
          if (u == t || flip[u] >= 0)
            continue;
          // u must traverse the edge as b->a.
          bool forward = false;
          for (int j = 0; j < 3; ++j)
            forward = forward || (triangles[3 * u + j] == a && triangles[3 * u + (j + 1) % 3] == b);
          flip[u] = forward ? 1 : 0;
          queue.push_back(u);
        }
      }
    }
  }
  for (int32_t t = 0; t < nt; ++t)
  {
    const int32_t s = triangleShell[t];
    if (s < 0)
      continue;
    const double v = det3(c, tri(t, 0), tri(t, 1), tri(t, 2)) / 6.0;
    shellVol[s].add(flip[t] ? -v : v);
  }
  Sum total;
  for (int32_t s = 0; s < nshell; ++s)
  {
    const double v = std::fabs(shellVol[s].value());
    const int d = s < static_cast<int32_t>(shellDepth.size()) ? shellDepth[s] : 0;
    if (rule == RegionRule::KeepAll)
    {
      if (d == 0)
        total.add(v);
    }
    else
      total.add((d % 2) ? -v : v);
  }
  return total.value();
}

} // namespace volgrid
