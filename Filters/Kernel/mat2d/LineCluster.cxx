#include "mat2d/LineCluster.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Regular_triangulation_2.h>
#include <CGAL/Regular_triangulation_face_base_2.h>
#include <CGAL/Regular_triangulation_vertex_base_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

namespace exactmat
{
namespace
{
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel,
  CGAL::Regular_triangulation_vertex_base_2<Kernel>>; // the line's index
using FaceBase = CGAL::Triangulation_face_base_with_info_2<int, Kernel,
  CGAL::Regular_triangulation_face_base_2<Kernel>>; // the node's index
using Structure = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using Regular = CGAL::Regular_triangulation_2<Kernel, Structure>;

/// Where lines i, j, l tie: (a_i − a_j)·y = c_j − c_i and (a_i − a_l)·y = c_l − c_i, in
/// extended precision (consecutive normals of a 10,000-gon differ by 6e-4: the system's
/// determinant is of the order of the cube of that).
ClusterNode tie(const std::vector<ClusterLine>& lines, int i, int j, int l)
{
  using Real = long double;
  const ClusterLine &li = lines[i], &lj = lines[j], &ll = lines[l];
  const Real a11 = Real(li.normal.x()) - Real(lj.normal.x()), a12 = Real(li.normal.y()) - Real(lj.normal.y());
  const Real a21 = Real(li.normal.x()) - Real(ll.normal.x()), a22 = Real(li.normal.y()) - Real(ll.normal.y());
  const Real b1 = Real(lj.offset) - Real(li.offset), b2 = Real(ll.offset) - Real(li.offset);
  const Real det = a11 * a22 - a12 * a21;
  ClusterNode n;
  n.lines = { i, j, l };
  const Real x = (b1 * a22 - b2 * a12) / det, y = (a11 * b2 - a21 * b1) / det;
  n.x = Vec2(static_cast<double>(x), static_cast<double>(y));
  Real r = 0.0;
  for (const ClusterLine* c : { &li, &lj, &ll })
    r += Real(c->normal.x()) * x + Real(c->normal.y()) * y + Real(c->offset);
  n.r = static_cast<double>(r / 3.0L);
  return n;
}
} // namespace

ClusterTree lineClusterTree(const std::vector<ClusterLine>& lines)
{
  ClusterTree tree;
  Regular rt;
  for (int j = 0; j < static_cast<int>(lines.size()); ++j)
  {
    const Vec2& a = lines[j].normal;
    // Lifted to height c_j above a_j: the power weight |a_j|² − c_j.
    const Regular::Weighted_point p(Kernel::Point_2(a.x(), a.y()), a.squaredNorm() - lines[j].offset);
    const Regular::Vertex_handle v = rt.insert(p);
    if (v != Regular::Vertex_handle())
      v->info() = j;
  }
  if (rt.dimension() < 2)
    return tree;
  for (auto f = rt.finite_faces_begin(); f != rt.finite_faces_end(); ++f)
  {
    f->info() = static_cast<int>(tree.nodes.size());
    tree.nodes.push_back(tie(lines, f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()));
  }
  for (auto e = rt.finite_edges_begin(); e != rt.finite_edges_end(); ++e)
  {
    const Regular::Face_handle f = e->first, g = f->neighbor(e->second);
    ClusterEdge c;
    c.lineA = f->vertex(f->cw(e->second))->info();
    c.lineB = f->vertex(f->ccw(e->second))->info();
    const bool fFinite = !rt.is_infinite(f), gFinite = !rt.is_infinite(g);
    c.node0 = fFinite ? f->info() : g->info();
    c.node1 = fFinite && gFinite ? g->info() : -1;
    tree.edges.push_back(c);
  }
  return tree;
}

} // namespace exactmat
