#pragma once
/// @file Polyhedra.h
/// @brief Solids with planar faces as exact boundary pieces: from vertex loops, boxes, and
/// random truncated pyramids (the 3D MAT's tests and benchmarks).

#include "brep/Boundary3D.h"

#include <functional>
#include <random>
#include <vector>

namespace exactmat
{

/// A polyhedron from vertices and faces (vertex index loops, either orientation): triangles
/// as linear triangles, planar quadrilaterals as bilinear patches, larger polygons as a fan
/// of coplanar triangles about their centroid (the edges between them are flat: smooth).
/// Entity = face index.
std::vector<PatchPiece> polyhedron(const Vec3List& vertices, const std::vector<std::vector<int>>& faces);

/// The box [−a, a] × [−b, b] × [−c, c].
std::vector<PatchPiece> boxPolyhedron(double a, double b, double c);

/// A random box (half-sides a 1…3, b 0.7…2.2, c 0.5…1.5) with a box-shaped cavity inside
/// (half-sides 0.15…0.75 of the smallest, each of the other two 0.6…1.4 times the first,
/// anywhere with its walls at least 5% of the box's half-sides from the box's): a second
/// shell, given outward like the first (Boundary3D turns it), whose edges are reflex.
/// Entities 0…5 the box's faces, 6…11 the cavity's.
std::vector<PatchPiece> randomBoxWithCavity(std::mt19937& rng);

/// The box [−a, a] × [−b, b] × [−c, c] whose top (z = c) is a bicubic patch with its four
/// inner control points raised by bulge·(1 + tilt·(i − 1.5)) (i along x): a free-form face
/// meeting four planar ones along straight convex edges.
std::vector<PatchPiece> boxWithFreeFormTop(double a, double b, double c, double bulge, double tilt);

/// The cube [0, b]³ with the corner cube [a, b]³ cut away (0 < a < b): three reflex edges
/// meeting at a reflex corner (a, a, a), and corners where they meet convex edges. Faces:
/// the three full sides, the three L-shaped sides each as two convex polygons (their common
/// edge is flat), the three notch squares.
std::vector<PatchPiece> notchedCube(double b, double a);

/// The prism over the L [0, 2b]² minus [b, 2b]² (legs b thick) from z = 0 to z = h: one
/// reflex edge (x = y = b), each cap as two convex quadrilaterals.
std::vector<PatchPiece> lPrism(double b, double h);

/// The union of the filled cells of an nx × ny × nz grid of unit cubes scaled by `cell`: one
/// square per exposed cell side (coplanar squares meet at smooth edges). The caller keeps
/// the union a manifold solid (no two cells meeting only along an edge or at a corner).
std::vector<PatchPiece> voxelSolid(const std::function<bool(int, int, int)>& filled, int nx, int ny, int nz, double cell = 1.0);

/// A random staircase: an n × n grid of columns whose heights (1 … maxHeight cells) never
/// increase along x or y, the first maxHeight, the last 1 — reflex edges, reflex corners and
/// corners where convex and reflex edges meet, always a manifold solid.
std::vector<PatchPiece> randomStaircase(std::mt19937& rng, int n, int maxHeight);

/// A truncated pyramid: a convex n-gon (vertices on a random ellipse at random angles) in
/// z = 0 and its image under a random homothety (ratio 0.3 … 0.9) moved up by 0.5 … 2: planar
/// trapezoid sides, convex; the caps are fans of n triangles.
std::vector<PatchPiece> randomFrustum(std::mt19937& rng, int n);

} // namespace exactmat
