#pragma once
/// @file DomainTriangulation.h
/// @brief A planar region bounded by polygon loops (holes allowed), triangulated with
/// CGAL's constrained Delaunay triangulation (exact predicates): every loop segment stays
/// a whole triangle side, the region is found by the parity of the loops crossed from
/// outside, and points can be added inside afterwards (refinement). Used for a CAD file's
/// planar faces and for the parameter domains of medial sheets.

#include "common/Types.h"

#include <array>
#include <memory>
#include <vector>

namespace exactmat
{

class DomainTriangulation
{
public:
  /// The loops' vertices are numbered loop after loop from 0. Two loops may touch at a
  /// vertex (its first number is the one triangles use). Throws InputError when a loop has
  /// fewer than three vertices, loops cross, or two vertices of one loop coincide.
  explicit DomainTriangulation(const std::vector<std::vector<Vec2>>& loops);
  ~DomainTriangulation();
  DomainTriangulation(const DomainTriangulation&) = delete;
  DomainTriangulation& operator=(const DomainTriangulation&) = delete;

  /// Adds a point strictly inside the region (a triangle's centroid, say) and returns its
  /// index (the next number), or −1 when it coincides with a vertex already there.
  int insert(const Vec2& p);
  int size() const;
  /// The triangles inside the region, counter-clockwise in the plane.
  std::vector<std::array<int, 3>> triangles() const;

private:
  struct Impl;
  std::unique_ptr<Impl> D;
};

} // namespace exactmat
