#include "geometry/DomainTriangulation.h"

#include "common/InputError.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_face_base_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <deque>

namespace exactmat
{
namespace
{
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>; // index + 1
using FaceInfo = CGAL::Triangulation_face_base_with_info_2<int, Kernel>;     // loops crossed
using FaceBase = CGAL::Constrained_triangulation_face_base_2<Kernel, FaceInfo>;
using Structure = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
// Loops that cross are bad input, not something to mend with new points.
using CDT = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Structure,
  CGAL::No_constraint_intersection_requiring_constructions_tag>;
} // namespace

struct DomainTriangulation::Impl
{
  CDT cdt;
  int count = 0;  // numbers given (the loops' vertices, then the points inserted)
  int shared = 0; // loop vertices at a point another loop has already
};

DomainTriangulation::DomainTriangulation(const std::vector<std::vector<Vec2>>& loops)
  : D(std::make_unique<Impl>())
{
  try
  {
    for (const std::vector<Vec2>& loop : loops)
    {
      if (loop.size() < 3)
        fail("a loop of ", loop.size(), " vertices");
      const int first = D->count + 1; // this loop's first number
      std::vector<CDT::Vertex_handle> handles;
      for (const Vec2& p : loop)
      {
        const size_t before = D->cdt.number_of_vertices();
        CDT::Vertex_handle v = D->cdt.insert(CDT::Point(p.x(), p.y()));
        ++D->count;
        if (D->cdt.number_of_vertices() == before)
        {
          // Two loops may touch at a point (a hole's seam meeting the outer one where it
          // only kisses it): the vertex keeps its first number. A loop through one point
          // twice is bad input.
          if (v->info() >= first)
            fail("two of its boundary vertices coincide");
          ++D->shared;
        }
        else
          v->info() = D->count;
        handles.push_back(v);
      }
      for (size_t k = 0; k < handles.size(); ++k)
        D->cdt.insert_constraint(handles[k], handles[(k + 1) % handles.size()]);
    }
  }
  catch (const CDT::Intersection_of_constraints_exception&)
  {
    fail("its boundary loops cross");
  }
  if (static_cast<int>(D->cdt.number_of_vertices()) != D->count - D->shared)
    fail("two of its boundary vertices coincide");
}

DomainTriangulation::~DomainTriangulation() = default;

int DomainTriangulation::insert(const Vec2& p)
{
  const size_t before = D->cdt.number_of_vertices();
  CDT::Vertex_handle v = D->cdt.insert(CDT::Point(p.x(), p.y()));
  if (D->cdt.number_of_vertices() == before)
    return -1;
  v->info() = ++D->count;
  return D->count - 1;
}

int DomainTriangulation::size() const
{
  return D->count;
}

std::vector<std::array<int, 3>> DomainTriangulation::triangles() const
{
  const CDT& cdt = D->cdt;
  // Every vertex on one line: the region has no area (and a 1-dimensional triangulation's
  // faces are not the ones walked below).
  if (cdt.dimension() < 2)
    return {};
  // Parity of the constrained edges crossed from the infinite face: odd = inside.
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f)
    f->info() = -1;
  std::deque<std::pair<CDT::Face_handle, int>> todo{ { cdt.infinite_face(), 0 } };
  while (!todo.empty())
  {
    auto [f, level] = todo.front();
    todo.pop_front();
    if (f->info() != -1)
      continue;
    f->info() = level;
    for (int i = 0; i < 3; ++i)
    {
      CDT::Face_handle g = f->neighbor(i);
      if (g->info() != -1)
        continue;
      if (cdt.is_constrained(CDT::Edge(f, i)))
        todo.push_back({ g, level + 1 });
      else
        todo.push_front({ g, level });
    }
  }
  std::vector<std::array<int, 3>> out;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if (f->info() % 2 == 1)
      out.push_back({ f->vertex(0)->info() - 1, f->vertex(1)->info() - 1, f->vertex(2)->info() - 1 });
  return out;
}

} // namespace exactmat
