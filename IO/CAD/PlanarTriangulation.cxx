#include "PlanarTriangulation.h"

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
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;
using FaceInfo = CGAL::Triangulation_face_base_with_info_2<int, Kernel>; // loops crossed, -1 unset
using FaceBase = CGAL::Constrained_triangulation_face_base_2<Kernel, FaceInfo>;
using Structure = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
// Loops that cross are bad input, not something to mend with new points.
using CDT = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Structure,
  CGAL::No_constraint_intersection_requiring_constructions_tag>;
} // namespace

std::vector<std::array<int, 3>> triangulatePlanarLoops(const std::vector<Vec3List>& loops, const Vec3& normal)
{
  // A frame of the plane with e1 × e2 = normal: counter-clockwise there is about the normal.
  const Vec3 n = normal.normalized();
  const Vec3 e1 = (std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).cross(n).normalized();
  const Vec3 e2 = n.cross(e1);
  CDT cdt;
  int count = 0;
  try
  {
    for (const Vec3List& loop : loops)
    {
      if (loop.size() < 3)
      {
        fail("a loop of ", loop.size(), " vertices");
      }
      std::vector<CDT::Vertex_handle> handles;
      for (const Vec3& p : loop)
      {
        // info() = index + 1; a vertex inserted twice is caught by the count below.
        CDT::Vertex_handle v = cdt.insert(CDT::Point(p.dot(e1), p.dot(e2)));
        v->info() = ++count;
        handles.push_back(v);
      }
      for (size_t k = 0; k < handles.size(); ++k)
      {
        cdt.insert_constraint(handles[k], handles[(k + 1) % handles.size()]);
      }
    }
  }
  catch (const CDT::Intersection_of_constraints_exception&)
  {
    fail("its boundary loops cross");
  }
  if (static_cast<int>(cdt.number_of_vertices()) != count)
  {
    fail("two of its boundary vertices coincide");
  }
  // Parity of the constrained edges crossed from the infinite face: odd = inside.
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f)
  {
    f->info() = -1;
  }
  std::deque<std::pair<CDT::Face_handle, int>> todo{ { cdt.infinite_face(), 0 } };
  while (!todo.empty())
  {
    auto [f, level] = todo.front();
    todo.pop_front();
    if (f->info() != -1)
    {
      continue;
    }
    f->info() = level;
    for (int i = 0; i < 3; ++i)
    {
      CDT::Face_handle g = f->neighbor(i);
      if (g->info() == -1)
      {
        const bool constrained = cdt.is_constrained(CDT::Edge(f, i));
        if (constrained)
        {
          todo.push_back({ g, level + 1 });
        }
        else
        {
          todo.push_front({ g, level });
        }
      }
    }
  }
  std::vector<std::array<int, 3>> triangles;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
  {
    if (f->info() % 2 == 1)
    {
      triangles.push_back({ f->vertex(0)->info() - 1, f->vertex(1)->info() - 1, f->vertex(2)->info() - 1 });
    }
  }
  return triangles;
}

} // namespace exactmat
