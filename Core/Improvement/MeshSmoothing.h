// Smoothing (paper 7.6): relocation of interior vertices, accepted only when the worst tet around the
// vertex gets better, never inverting a tet and never moving a boundary vertex.
//
// Quality: the paper accepts a Laplacian move when the minimum dihedral angle of the affected tets
// improves. We measure min over the star of tetSineQuality() (TetEditor.h: the smallest sine of the six
// dihedral angles), i.e. min(theta_min, 180 - theta_max): it is the paper's minimum dihedral angle, and it
// also refuses moves that open a dihedral angle towards 180 degrees (a flat "cap" has no small angle
// away from 0 but is as bad for a solver).
// Moves:
//   1. Laplacian (paper eq. 6): the centroid of the vertex's neighbours (vertices sharing an edge).
//   2. If rejected and options.optimize: an optimisation-based move that maximises the minimum quality of
//      the star (non-smooth hill climbing: the direction is the gradient of the worst tet's quality, or of
//      the mean of the normalised gradients of the nearly-worst tets, followed by a halving line search
//      that accepts only strict improvements of the star's minimum).
// Validity: every candidate position is written into mesh.points and every tet of the star is checked with
// the exact orient3d; a move is kept only when all are strictly positive. Locked vertices (on a face
// without neighbour, on a constrained face, or locked by the caller) never move.
#pragma once

#include "Progress.h"
#include "Status.h"
#include "TetEditor.h"
#include "TetMesh.h"

#include <cstdint>
#include <vector>

namespace volgrid
{

struct SmoothingOptions
{
  int passes = 3;              // sweeps over the vertices
  bool optimize = true;        // optimisation-based move when the Laplacian move is rejected
  int optimizeIterations = 12; // hill-climbing steps per vertex
  // Only vertices whose star is worse than this (in degrees of min(theta_min, 180 - theta_max)) are
  // smoothed; 90 = every vertex.
  double belowDegrees = 90.0;
};

struct SmoothingReport
{
  int passes = 0;
  int64_t laplacianMoves = 0;
  int64_t optimizedMoves = 0;
  int64_t rejected = 0; // vertices examined and left in place
  double seconds = 0;
};

enum class SmoothMove
{
  None,
  Laplacian,
  Optimized
};

// One vertex (the editor's vertex map must be current). The caller checks that v is not locked.
SmoothMove smoothVertex(TetEditor& editor, int32_t v, const SmoothingOptions& options);

// The same move, with v's star (the tets holding v) and neighbours (the vertices sharing an edge with v)
// given by the caller. It writes only v's coordinates and reads those of its star, so vertices that share
// no tet can move at the same time on different threads (ColouredSmoothing.h).
SmoothMove smoothVertexInStar(TetMesh& mesh, int32_t v, const int32_t* star, size_t starSize, const int32_t* nbrs,
                              size_t nbrCount, const SmoothingOptions& options);

// The same move for an objective other than the star's worst quality: tet i of `star` scores
// weight[i] * its quality, the move maximises the star's smallest score, and no position is taken where a
// tet's quality falls under floorQ[i] (each floor at most the tet's quality now). InteriorPolish.h weighs
// tets by the angle each must reach.
SmoothMove smoothVertexWeighted(TetMesh& mesh, int32_t v, const std::vector<int32_t>& star,
                                const std::vector<int32_t>& nbrs, const std::vector<double>& weight,
                                const std::vector<double>& floorQ, const SmoothingOptions& options);

// Smooth every unlocked vertex. locked: optional extra per-vertex locks (non-zero = keep), OR-ed with the
// vertices of constrained faces. Errors: InvalidOption (ghost tets present), Cancelled.
Status smoothMesh(TetMesh& mesh, const FaceConstraints* constraints, const std::vector<uint8_t>* locked,
                  const SmoothingOptions& options, Progress* progress = nullptr, SmoothingReport* report = nullptr);

} // namespace volgrid
