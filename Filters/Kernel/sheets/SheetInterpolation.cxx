#include "sheets/SheetInterpolation.h"
#include "sheets/SheetSide.h"
#include "sheets/CapSheet.h"
#include "sheets/RimSheet.h"

#include "sheets/TransitionSheets.h"

#include "common/InputError.h"
#include "geometry/ClosestPoint.h"
#include "geometry/DomainTriangulation.h"
#include "geometry/PatchContinuation.h"
#include "mat3d/PatchBoundary.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <cmath>
#include <limits>
#include <map>
#include <set>

namespace exactmat
{

double MedialSheetMesh::area() const
{
  double sum = 0.0;
  for (const auto& t : triangles)
    sum += 0.5 * (vertices[t[1]].x - vertices[t[0]].x).cross(vertices[t[2]].x - vertices[t[0]].x).norm();
  return sum;
}

namespace
{

class SheetBuilder

{
public:
  /// byEdge (0 or 1) for a pair of reflex edges: parameterise by that edge's touch
  /// parameters (t, θ) instead of a plane fitted to the border (curvedEdgePair).
  SheetBuilder(const Boundary3D& boundary, const std::vector<Generator3D>& generators, const std::vector<int>& a,
    const std::vector<int>& b, const SheetOptions& options, int byEdge = -1)
    : B(boundary)
    , Options(options)
    , Size(boundary.diagonal())
    , Side{ { SheetSide(boundary, generators, a), SheetSide(boundary, generators, b) } }
  {
    Mesh.generators = { { a.front(), b.front() } };
    Mesh.members = { { a, b } };
    // Parameterise by a face when the pair has one (its touchpoint map is regular up to
    // the border, radius 0 included); a reflex edge's or corner's angle is undefined there.
    Mesh.parameterisedBy =
      Side[0].kind() != GeneratorKind3D::Face && Side[1].kind() == GeneratorKind3D::Face ? 1 : 0;
    P = Mesh.parameterisedBy;
    O = 1 - P;
    Projected = Side[0].kind() != GeneratorKind3D::Face && Side[1].kind() != GeneratorKind3D::Face;
    Rounding = boundary.userFrame().inputRounding();
    Touch = slack(1e-8, 1e3);
    if (Projected && byEdge >= 0)
    {
      Projected = false;
      Mesh.parameterisedBy = P = byEdge;
      O = 1 - P;
    }
  }

  std::string name() const { return "the sheet of " + Side[0].name() + " and " + Side[1].name(); }

  // Two reflex edges, one of them curved (a revolved profile's reflex corners: two arcs):
  // the sheet between them is not planar, and a plane fitted to its border parameterises
  // it only between straight edges; each edge's own (t, θ) may (where the other's touch
  // moves regularly with it).
  bool curvedEdgePair() const
  {
    return Side[0].kind() == GeneratorKind3D::ReflexEdge && Side[1].kind() == GeneratorKind3D::ReflexEdge &&
      Side[0].members().size() == 1 && Side[1].members().size() == 1 && (curvedEdge(0) || curvedEdge(1));
  }

  MedialSheetMesh build(const std::vector<SheetBorderCurve>& curves, const std::vector<int>& convexEdges)
  {
    std::vector<std::vector<SheetVertex>> pieces;
    for (const SheetBorderCurve& curve : curves)
      addCurvePieces(curve, pieces);
    for (int e : convexEdges)
      pieces.push_back(convexEdgePiece(e));
    if (pieces.empty())
      fail("3D MAT sheets: ", name(), " has no border on its seams or convex edges");
    // Pieces whose balls are all one (a degenerate junction's triplets repeat it) bound
    // nothing; a pair with no other border has no sheet: nothing to fill, nothing wrong.
    pieces.erase(std::remove_if(pieces.begin(), pieces.end(),
                   [this](const std::vector<SheetVertex>& piece) {
                     for (const SheetVertex& v : piece)
                       if ((v.x - piece.front().x).norm() > Touch)
                         return false;
                     return true;
                   }),
      pieces.end());
    if (pieces.empty())
      return std::move(Mesh);
    addReflexCorners(pieces);
    if (Projected)
      fitPlane(pieces);
#ifdef EXACTMAT_SHEET_DEBUG
    std::fprintf(stderr, "%s: %zu pieces\n", name().c_str(), pieces.size());
    for (const auto& piece : pieces)
      std::fprintf(stderr, "  %zu points: (%.6g %.6g %.6g) r %.6g q (%.6g %.6g) -> (%.6g %.6g %.6g) r %.6g q (%.6g %.6g)\n",
        piece.size(), piece.front().x.x(), piece.front().x.y(), piece.front().x.z(), piece.front().r,
        piece.front().domain.x(), piece.front().domain.y(), piece.back().x.x(), piece.back().x.y(),
        piece.back().x.z(), piece.back().r, piece.back().domain.x(), piece.back().domain.y());
#endif
    const std::vector<std::vector<SheetVertex>> loops = chain(pieces);
    triangulate(loops);
    return std::move(Mesh);
  }

private:
  const Boundary3D& B;
  const SheetOptions& Options;
  double Size;
  /// The input's own rounding in the unit frame (Normalisation::inputRounding): a solid
  /// far from the origin is known only to it, and so are its seams (MAT3D polishes them to
  /// 64 times it). Every "same point" test below is the larger of a fixed fraction of the
  /// size and a multiple of it, so a moved solid gives the same sheets.
  double Rounding;
  double Touch;
  double slack(double fraction, double roundings) const { return std::max(fraction, roundings * Rounding) * Size; }
  std::array<SheetSide, 2> Side;
  int P = 0, O = 1; ///< which side carries the parameter domain, and the other
  bool Projected = false; ///< the domain is a plane's (two reflex entities), not P's
  Vec3 Origin = Vec3::Zero(), Axis0 = Vec3::Zero(), Axis1 = Vec3::Zero(), Normal = Vec3::Zero();
  MedialSheetMesh Mesh;

  // A sheet with a reflex edge or corner reaches radius 0 at the vertices where that entity
  // meets the other side (the L prism's sheet of its floor and its reflex edge ends at the
  // edge's foot), a point no seam or convex edge brings: such vertices join as one-point
  // pieces, so the border's free ends are joined through them, not across.
  void addReflexCorners(std::vector<std::vector<SheetVertex>>& pieces) const
  {
    if ((Side[0].kind() == GeneratorKind3D::Face) == (Side[1].kind() == GeneratorKind3D::Face))
      return; // two faces meet along convex edges; two reflex entities close on a rim
    for (const Vertex3D& vertex : B.vertices())
    {
      SheetVertex v;
      if (!onSheet(vertex.point, 0.0, v))
        continue;
      bool known = false;
      for (const auto& piece : pieces)
        for (const SheetVertex& w : piece)
          known = known || (w.x - v.x).norm() <= Touch;
      if (!known)
        pieces.push_back({ v });
    }
  }

  // How far outside its domain a touch parameter of gen may be for a ball of radius r.
  // A reflex edge's or corner's parameters are angles of the normal, known to the centre's
  // accuracy over the radius: a seam's end ball (a junction, placed to Touch) touching
  // where the edge meets a face has its angle at the limit only within Touch / r.
  double parameterSlack(const SheetSide& gen, double r) const
  {
    return gen.kind() == GeneratorKind3D::Face ? Touch : std::min(1e-4, Touch / std::max(r, Touch));
  }

  // The parameter of g's touch of the ball (x, r), when the ball touches g there along
  // g's normal (a touch on g's border counts; radius 0: x on g).
  bool touches(const SheetSide& gen, const Vec3& x, double r, Vec2& q) const
  {
    const Vec3 foot = gen.nearestPoint(x);
    if (r <= Touch)
    {
      q = gen.parameterOf(x);
      return (foot - x).norm() <= Touch;
    }
    q = gen.touchParameter(foot, x);
    const Touch3D t = gen.evaluate(q);
    return (t.point + r * t.normal - x).norm() <= Touch && gen.exitSide(q, parameterSlack(gen, r)) < 0;
  }

  // A ball of the curve on this sheet, with its touches; false when it is not.
  bool onSheet(const Vec3& x, double r, SheetVertex& v) const
  {
    Vec2 qp, qo;
    if (!touches(Side[P], x, r, qp) || !touches(Side[O], x, r, qo))
      return false;
    v.x = x;
    v.r = r;
    v.q[P] = qp;
    v.q[O] = qo;
    v.domain = Projected ? planeCoordinates(x) : qp;
    v.touch[P] = Side[P].evaluate(qp).point;
    v.touch[O] = r <= Touch ? x : Side[O].evaluate(qo).point;
    v.border = true;
    return true;
  }

  void addCurvePieces(const SheetBorderCurve& curve, std::vector<std::vector<SheetVertex>>& pieces) const
  {
    std::vector<SheetVertex> run;
    auto flush = [&]() {
      if (run.size() >= 2)
        pieces.push_back(run);
      run.clear();
    };
    for (size_t i = 0; i < curve.centres.size(); ++i)
    {
      SheetVertex v;
      if (onSheet(curve.centres[i], curve.radii[i], v))
      {
        v.source = i < curve.ids.size() ? curve.ids[i] : -1;
        run.push_back(v);
      }
      else
        flush();
    }
    flush();
  }

  // The convex edge's points, radius 0, sampled until chords are within the tolerance and
  // no longer than maxEdge.
  std::vector<SheetVertex> convexEdgePiece(int e) const
  {
    const Edge3D& edge = B.edges()[e];
    const BezierCurve side = B.faces()[edge.faceA].patch.side(edge.sideA);
    std::vector<double> ts{ 0.0 };
    std::vector<std::pair<double, double>> todo{ { 0.0, 1.0 } };
    std::vector<std::pair<double, double>> done;
    for (int guard = 0; !todo.empty() && guard < 100000; ++guard)
    {
      auto [t0, t1] = todo.back();
      todo.pop_back();
      const Vec3 p0 = side.evaluate(t0), p1 = side.evaluate(t1), pm = side.evaluate(0.5 * (t0 + t1));
      const bool split = t1 - t0 > 1e-6 &&
        ((p1 - p0).norm() > Options.maxEdge * Size || (pm - 0.5 * (p0 + p1)).norm() > Options.tolerance * Size);
      if (split)
      {
        todo.push_back({ 0.5 * (t0 + t1), t1 });
        todo.push_back({ t0, 0.5 * (t0 + t1) });
      }
      else
        ts.push_back(t1);
    }
    std::vector<SheetVertex> piece;
    for (double t : ts)
    {
      SheetVertex v;
      v.x = side.evaluate(t);
      v.r = 0.0;
      v.q[P] = Side[P].parameterOf(v.x);
      v.domain = v.q[P];
      v.q[O] = Side[O].parameterOf(v.x);
      v.touch = { { v.x, v.x } };
      v.border = true;
      v.convexEdge = true;
      piece.push_back(v);
    }
    return piece;
  }

  // A ball no other part of the boundary enters (when the exact boundary is known).
  bool medial(const SheetVertex& v) const
  {
    return !Options.exact || std::abs(Options.exact->distance(v.x) - v.r) <= slack(1e-9, 64.0);
  }

  // The ball touching P at qp and O: Newton on (q_O, r) from the guess in v; the
  // bracketed distance root when Newton does not land on O.
  bool solve(const Vec2& qp, SheetVertex& v) const
  {
    if (Projected)
      return solveProjected(qp, v);
    const Touch3D tp = Side[P].evaluate(qp);
    Vec2 qo = v.q[O];
    double r = v.r;
    auto inside = [&]() { return r >= -Touch && Side[O].exitSide(qo, parameterSlack(Side[O], r)) < 0; };
    // Newton from the neighbour may settle on another branch of O's touch (a reflex edge's
    // normal angle θ is periodic: from a guess at the far side of the arc it found θ = 0
    // a billion turns away, off the arc): then from the bracketed radius.
    if (!newton(tp, qo, r) || !inside())
    {
      qo = v.q[O];
      r = v.r;
      if (!bracket(tp, qo, r) || !newton(tp, qo, r) || !inside())
        return false;
    }
    v.x = tp.point + r * tp.normal;
    v.r = std::max(r, 0.0);
    v.q[P] = qp;
    v.q[O] = qo;
    v.domain = qp;
    v.touch[P] = tp.point;
    v.touch[O] = Side[O].evaluate(qo).point;
    v.source = -1;
    v.border = v.convexEdge = false;
    return true;
  }

  // A sheet between two reflex entities (edges, corners) has no face to carry its domain
  // (their touch parameters stay fixed along a rim): the domain is the plane fitted to its
  // border balls' centres instead, and a point (u, v) there is the ball whose centre lies
  // on the plane's normal through it: Newton on both touches, the height and the radius.
  Vec2 planeCoordinates(const Vec3& x) const { return Vec2((x - Origin).dot(Axis0), (x - Origin).dot(Axis1)); }

  void fitPlane(std::vector<std::vector<SheetVertex>>& pieces)
  {
    Vec3 sum = Vec3::Zero();
    int n = 0;
    for (const auto& piece : pieces)
      for (const SheetVertex& v : piece)
      {
        sum += v.x;
        ++n;
      }
    Origin = sum / std::max(n, 1);
    Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
    for (const auto& piece : pieces)
      for (const SheetVertex& v : piece)
        scatter += (v.x - Origin) * (v.x - Origin).transpose();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(scatter);
    Normal = eigen.eigenvectors().col(0);
    Axis0 = eigen.eigenvectors().col(2);
    Axis1 = Normal.cross(Axis0);
    for (auto& piece : pieces)
      for (SheetVertex& v : piece)
        v.domain = planeCoordinates(v.x);
  }

  bool solveProjected(const Vec2& uv, SheetVertex& v) const
  {
    const Vec3 base = Origin + uv.x() * Axis0 + uv.y() * Axis1;
    Vec2 qa = v.q[0], qb = v.q[1];
    double w = (v.x - base).dot(Normal), r = v.r;
    bool converged = false;
    for (int it = 0; it < 40 && !converged; ++it)
    {
      const Touch3D ta = Side[0].evaluate(qa), tb = Side[1].evaluate(qb);
      const Vec3 x = base + w * Normal;
      Eigen::Matrix<double, 6, 1> f;
      f << ta.point + r * ta.normal - x, tb.point + r * tb.normal - x;
      Eigen::Matrix<double, 6, 6> j = Eigen::Matrix<double, 6, 6>::Zero();
      j.block<3, 2>(0, 0) = ta.dPoint + r * ta.dNormal;
      j.block<3, 2>(3, 2) = tb.dPoint + r * tb.dNormal;
      j.block<3, 1>(0, 4) = -Normal;
      j.block<3, 1>(3, 4) = -Normal;
      j.block<3, 1>(0, 5) = ta.normal;
      j.block<3, 1>(3, 5) = tb.normal;
      const Eigen::Matrix<double, 6, 1> d = j.colPivHouseholderQr().solve(-f);
      if (!d.allFinite())
        return false;
      qa += d.segment<2>(0);
      qb += d.segment<2>(2);
      w += d(4);
      r += d(5);
      if (!std::isfinite(r) || std::abs(r) > 4.0 * Size || std::abs(w) > 4.0 * Size)
        return false;
      converged = d.norm() <= 1e-15 * (1.0 + qa.norm() + qb.norm() + std::abs(w) + std::abs(r)) ||
        f.norm() <= 1e-15 * Size;
    }
    const Touch3D ta = Side[0].evaluate(qa), tb = Side[1].evaluate(qb);
    const Vec3 x = base + w * Normal;
    if ((ta.point + r * ta.normal - x).norm() > slack(1e-12, 64.0) || (tb.point + r * tb.normal - x).norm() > slack(1e-12, 64.0))
      return false;
    if (r < -Touch || Side[0].exitSide(qa, parameterSlack(Side[0], r)) >= 0 ||
      Side[1].exitSide(qb, parameterSlack(Side[1], r)) >= 0)
      return false;
    v.x = x;
    v.r = std::max(r, 0.0);
    v.q = { { qa, qb } };
    v.domain = uv;
    v.touch = { { ta.point, tb.point } };
    v.source = -1;
    v.border = v.convexEdge = false;
    return true;
  }

  bool newton(const Touch3D& tp, Vec2& qo, double& r) const
  {
    for (int it = 0; it < 40; ++it)
    {
      const Touch3D to = Side[O].evaluate(qo);
      const Vec3 f = tp.point + r * tp.normal - to.point - r * to.normal;
      Eigen::Matrix3d j;
      j.col(0) = -(to.dPoint.col(0) + r * to.dNormal.col(0));
      j.col(1) = -(to.dPoint.col(1) + r * to.dNormal.col(1));
      j.col(2) = tp.normal - to.normal;
      const Vec3 d = j.colPivHouseholderQr().solve(-f);
      if (!d.allFinite())
        return false;
      qo += d.head<2>();
      r += d(2);
      if (!std::isfinite(r) || std::abs(r) > 4.0 * Size)
        return false;
      if (d.norm() <= 1e-15 * (1.0 + qo.norm() + std::abs(r)) || f.norm() <= 1e-15 * Size)
      {
        const Touch3D end = Side[O].evaluate(qo);
        return (tp.point + r * tp.normal - end.point - r * end.normal).norm() <= slack(1e-12, 64.0);
      }
    }
    const Touch3D end = Side[O].evaluate(qo);
    return (tp.point + r * tp.normal - end.point - r * end.normal).norm() <= slack(1e-12, 64.0);
  }

  // distance(S + rN, O) − r falls monotonically in r (a distance changes at most as fast
  // as its argument moves): bisection between 0 and the first radius where it is negative.
  bool bracket(const Touch3D& tp, Vec2& qo, double& r) const
  {
    auto f = [&](double s) { return Side[O].distance(tp.point + s * tp.normal) - s; };
    double lo = 0.0, hi = std::max(f(0.0), 1e-3 * Size);
    for (int k = 0; f(hi) >= 0.0; ++k)
    {
      if (k > 12)
        return false;
      lo = hi;
      hi *= 2.0;
    }
    for (int k = 0; k < 80 && hi - lo > 1e-16 * Size; ++k)
    {
      const double mid = 0.5 * (lo + hi);
      (f(mid) >= 0.0 ? lo : hi) = mid;
    }
    r = 0.5 * (lo + hi);
    const Vec3 x = tp.point + r * tp.normal;
    qo = Side[O].touchParameter(Side[O].nearestPoint(x), x);
    return true;
  }

  // Pieces joined into loops where they share a ball; free ends joined along straight
  // lines of P's parameters.
  std::vector<std::vector<SheetVertex>> chain(std::vector<std::vector<SheetVertex>>& pieces)
  {
    const double join = Touch;
    std::vector<bool> used(pieces.size(), false);
    std::vector<std::vector<SheetVertex>> loops;
    const size_t guardMax = 4 * pieces.size() + 8;
    for (size_t start = 0; start < pieces.size(); ++start)
    {
      if (used[start] || pieces[start].size() < 2)
        continue; // a corner's one-point piece joins a loop, it does not start one
      used[start] = true;
      std::vector<SheetVertex> loop = pieces[start];
      bool closed = false;
      for (size_t guard = 0; guard < guardMax && !closed; ++guard)
      {
        const SheetVertex& end = loop.back();
        if (loop.size() >= 3 && (end.x - loop.front().x).norm() <= join)
        {
          loop.pop_back();
          closed = true;
          break;
        }
        // A piece sharing the end's ball.
        int next = -1;
        bool reversed = false;
        for (size_t j = 0; j < pieces.size() && next < 0; ++j)
        {
          if (used[j])
            continue;
          if ((pieces[j].front().x - end.x).norm() <= join)
            next = static_cast<int>(j);
          else if ((pieces[j].back().x - end.x).norm() <= join)
          {
            next = static_cast<int>(j);
            reversed = true;
          }
        }
        if (next < 0)
        {
          // None at the end: grow the loop at its start first (a gap is taken only
          // between ends that share no ball with any piece).
          int before = -1;
          bool flip = false;
          for (size_t j = 0; j < pieces.size() && before < 0; ++j)
          {
            if (used[j])
              continue;
            if ((pieces[j].back().x - loop.front().x).norm() <= join)
              before = static_cast<int>(j);
            else if ((pieces[j].front().x - loop.front().x).norm() <= join)
            {
              before = static_cast<int>(j);
              flip = true;
            }
          }
          if (before >= 0)
          {
            used[before] = true;
            std::vector<SheetVertex> piece = pieces[before];
            if (flip)
              std::reverse(piece.begin(), piece.end());
            loop.insert(loop.begin(), piece.begin(), piece.end() - 1);
            continue;
          }
        }
        if (next < 0)
        {
          // No partner: the border runs on along a side of P's or O's face (where the
          // pair's sheet goes on as another pair's: across a smooth edge, onto a reflex
          // edge). Join the nearest free end (or the loop's start) in P's parameters that
          // lies on a side the end lies on and its own piece does not run along; the
          // nearest of all when no end shares one.
          const std::vector<std::pair<int, int>> endSides = freeSides(loop);
          const Vec2 qe = end.domain;
          double best = std::numeric_limits<double>::infinity();
          bool bestShares = false;
          std::vector<std::pair<int, int>> bestSides;
          struct Candidate
          {
            double distance;
            int piece;
            bool reversed;
            std::vector<std::pair<int, int>> sides;
          };
          std::vector<Candidate> candidates;
          auto consider = [&](const SheetVertex& v, const std::vector<std::pair<int, int>>& sides, int j, bool rev) {
            candidates.push_back({ (v.domain - qe).norm(), j, rev, sides });
            bool shares = false;
            for (const auto& side : sides)
              shares = shares || std::find(endSides.begin(), endSides.end(), side) != endSides.end();
            const double d = (v.domain - qe).norm();
            if ((shares && !bestShares) || (shares == bestShares && d < best))
            {
              best = d;
              bestShares = shares;
              bestSides = sides;
              next = j;
              reversed = rev;
            }
          };
          std::vector<SheetVertex> front(loop.rbegin(), loop.rend());
          consider(loop.front(), freeSides(front), -1, false);
          for (size_t j = 0; j < pieces.size(); ++j)
          {
            if (used[j])
              continue;
            std::vector<SheetVertex> backwards(pieces[j].rbegin(), pieces[j].rend());
            consider(pieces[j].front(), freeSides(backwards), static_cast<int>(j), false);
            consider(pieces[j].back(), freeSides(pieces[j]), static_cast<int>(j), true);
          }
          auto endOf = [&](int j, bool rev) -> const SheetVertex& {
            return j < 0 ? loop.front() : (rev ? pieces[j].back() : pieces[j].front());
          };
          auto arrivalAt = [&](int j, bool rev) {
            return j < 0 ? arrival(loop.begin(), loop.end())
                         : (rev ? arrival(pieces[j].rbegin(), pieces[j].rend()) : arrival(pieces[j].begin(), pieces[j].end()));
          };
          // A loop about to close on itself straight across the sheet (ends on different
          // sides with no path of sheet points along sides between them, onto a chord of
          // its own piece) while other pieces are free: rather the nearest of their ends a
          // path along sides reaches. (The sheet of a face and a cavity's edge whose two
          // seams each run from the edge's normal-arc end to one of its ends: each closed on
          // itself, two slivers. A straight gap to another piece stays: two pieces of
          // a surface of revolution's sheet meet across a cap's line.)
          std::vector<SheetVertex> sidePath;
          std::vector<std::pair<int, int>> chain;
          if (!bestShares)
            chain = curvedSideChain(endSides, bestSides);
          std::vector<SheetVertex> around;
          const bool aroundEdge = !bestShares && chain.empty() && aroundCurvedEdge(loop.back(), endOf(next, reversed), around);
          if (!bestShares && chain.empty() && !aroundEdge)
          {
            const std::array<Vec2, 2> arrivals{ { arrival(loop.rbegin(), loop.rend()), arrivalAt(next, reversed) } };
            sidePath = cornersBetween(loop.back(), endSides, endOf(next, reversed), bestSides, arrivals);
            if (sidePath.empty() && next < 0)
            {
              std::sort(candidates.begin(), candidates.end(),
                [](const Candidate& x, const Candidate& y) { return x.distance < y.distance; });
              for (const Candidate& c : candidates)
              {
                if (c.piece < 0)
                  continue;
                std::vector<SheetVertex> path = cornersBetween(loop.back(), endSides, endOf(c.piece, c.reversed), c.sides,
                  { { arrivals[0], arrivalAt(c.piece, c.reversed) } });
                if (path.empty())
                  continue;
                next = c.piece;
                reversed = c.reversed;
                bestSides = c.sides;
                sidePath = std::move(path);
                break;
              }
            }
          }
          const SheetVertex target = endOf(next, reversed);
#ifdef EXACTMAT_SHEET_DEBUG
          std::fprintf(stderr, "  gap from (%.6g %.6g %.6g) to (%.6g %.6g %.6g) piece %d shares %d; end sides:", end.x.x(),
            end.x.y(), end.x.z(), target.x.x(), target.x.y(), target.x.z(), next, (int)bestShares);
          for (const auto& side : endSides)
            std::fprintf(stderr, " (%d,%d)", side.first, side.second);
          std::fprintf(stderr, "; target sides:");
          for (const auto& side : bestSides)
            std::fprintf(stderr, " (%d,%d)", side.first, side.second);
          std::fprintf(stderr, "\n");
#endif
          // Ends on different sides: the border turns where those sides meet (or along a
          // third side between them).
          // Ends on two curved sides of one side's faces that a chain of its border sides
          // joins end to end (a revolved profile's reflex edge is an arc per quarter turn):
          // the border follows the chain, through the points where its sides meet.
          if (!chain.empty())
            for (size_t k = 0; k + 1 < chain.size(); ++k)
            {
              SheetVertex corner;
              if (!sideJoint(chain[k], chain[k + 1], loop.back(), corner))
                fail("3D MAT sheets: the border of ", name(), " cannot turn where two sides of ", Side[P].name(),
                  " or ", Side[O].name(), " meet");
              appendGap(loop, corner, chain[k]);
              loop.push_back(corner);
              ++Mesh.gapVertices;
            }
          else if (aroundEdge)
            for (const SheetVertex& corner : around)
            {
              appendGap(loop, corner);
              loop.push_back(corner);
              ++Mesh.gapVertices;
            }
          else
            for (const SheetVertex& corner : sidePath)
            {
              appendGap(loop, corner);
              loop.push_back(corner);
              ++Mesh.gapVertices;
            }
          // Ends on one side: the border follows it (a curved side — a revolved profile's
          // reflex edge, an arc — is not a straight line in P's parameters).
          std::pair<int, int> along{ -1, -1 };
          if (!chain.empty())
            along = chain.back();
          else if (bestShares)
            for (const auto& side : endSides)
              if (side.first >= 0 && std::find(bestSides.begin(), bestSides.end(), side) != bestSides.end() &&
                curvedSide(side))
                along = side;
          appendGap(loop, target, along);
          if (next < 0)
          {
            closed = true;
            break;
          }
        }
        used[next] = true;
        std::vector<SheetVertex> piece = pieces[next];
        if (reversed)
          std::reverse(piece.begin(), piece.end());
        const bool shared = (piece.front().x - loop.back().x).norm() <= join;
        loop.insert(loop.end(), piece.begin() + (shared ? 1 : 0), piece.end());
      }
      if (!closed)
        fail("3D MAT sheets: the border of ", name(), " does not close");
      // Repeated parameters (a ball met twice along the border, or two balls touching P at
      // one point, where a seam passes through a corner of P) would be one domain vertex.
      std::vector<SheetVertex> clean;
      for (const SheetVertex& v : densified(loop))
        if (clean.empty() || (v.domain - clean.back().domain).norm() > slack(1e-9, 1e3) / Size)
          clean.push_back(v);
      while (clean.size() > 1 && (clean.back().domain - clean.front().domain).norm() <= slack(1e-9, 1e3) / Size)
        clean.pop_back();
      withoutSpikes(clean);
      if (clean.size() < 3)
        continue; // a stretch that folds back on itself bounds no area
      loops.push_back(std::move(clean));
    }
    if (loops.empty())
      fail("3D MAT sheets: the border of ", name(), " encloses no area");
    return loops;
  }

  // A closed border that turns straight back over a step much shorter than the next (a run
  // from a neighbour's border starting a rounding's width before the arc it follows: the
  // turned cavity's corner sheets) crosses itself there and bounds nothing with that step:
  // the vertex is dropped — or, when it is a seam's point (kept: the seams' points are
  // shared with the seams), the short step's other end.
  static void withoutSpikes(std::vector<SheetVertex>& loop)
  {
    for (size_t guard = loop.size(); guard > 0 && loop.size() >= 4; --guard)
    {
      const size_t n = loop.size();
      size_t drop = n;
      for (size_t i = 0; i < n && drop == n; ++i)
      {
        const size_t before = (i + n - 1) % n, after = (i + 1) % n;
        const Vec2 in = loop[i].domain - loop[before].domain, out = loop[after].domain - loop[i].domain;
        const double a = in.norm(), b = out.norm();
        if (!(in.dot(out) < -0.99 * a * b) || std::min(a, b) > 0.05 * std::max(a, b))
          continue;
        const size_t across = a < b ? before : after; // the short step's other end
        if (loop[i].source < 0)
          drop = i;
        else if (loop[across].source < 0)
          drop = across;
      }
      if (drop == n)
        return;
      loop.erase(loop.begin() + static_cast<std::ptrdiff_t>(drop));
    }
  }

  // The face sides (generator, patch side) the last vertex of `run` touches its faces
  // on, leaving out those the run's middle lies on too (the side it runs along).
  std::vector<std::pair<int, int>> freeSides(const std::vector<SheetVertex>& given) const
  {
    const double near = slack(1e-7, 1e4);
    // One vertex per ball: a seam that changes triplets at a crossing lands several balls
    // on one point, and a middle taken among those would be the end itself.
    std::vector<SheetVertex> run;
    for (const SheetVertex& v : given)
      if (run.empty() || (v.x - run.back().x).norm() > Touch)
        run.push_back(v);
      else
        run.back() = v;
    std::vector<std::pair<int, int>> out;
    for (int g : { P, O })
      for (const Generator3D* member : Side[g].members())
      {
        if (member->kind() != GeneratorKind3D::Face)
          continue;
        const BezierPatch& patch = B.faces()[member->entity()].patch;
        for (int side = 0; side < 4; ++side)
        {
        const BezierCurve curve = patch.side(side);
        if ((curve.endPoint() - curve.startPoint()).norm() <= near && curve.degree() <= 1)
          continue; // a collapsed side (a triangle's corner)
        auto on = [&](const Vec3& touch) { return closestPoint(curve, touch).distance <= near; };
        // The run's middle: its middle vertex, or the chord's midpoint for two.
        const Vec3 middle = run.size() >= 3 ? run[run.size() / 2].touch[g]
                                            : 0.5 * (run.front().touch[g] + run.back().touch[g]);
        if (on(run.back().touch[g]) && !(run.size() >= 2 && on(middle)))
          out.emplace_back(member->entity(), side);
        }
      }
    // A reflex edge on the other side: its normal arc's ends (θ = 0, θ = α, where the
    // sheet goes on as one with the edge's faces) and its ends (t = 0, 1).
    if (Side[O].kind() == GeneratorKind3D::ReflexEdge && Side[O].members().size() == 1)
    {
      auto onEdgeSide = [&](const Vec2& q, int side) {
        const Generator3D& e = Side[O].first();
        const double value[4] = { q.y(), q.y() - e.edgeAngle(q.x()), q.x(), q.x() - 1.0 };
        return std::abs(value[side]) <= slack(1e-7, 1e4) / Size;
      };
      for (int side = 0; side < 4; ++side)
      {
        const Vec2 middle = run.size() >= 3 ? run[run.size() / 2].q[O] : 0.5 * (run.front().q[O] + run.back().q[O]);
        if (onEdgeSide(run.back().q[O], side) && !(run.size() >= 2 && onEdgeSide(middle, side)))
          out.emplace_back(edgeSideKey(), side);
      }
    }
    return out;
  }

  /// Sides are (face, patch side); a reflex edge's are (edgeSideKey(), 0 … 3).
  int edgeSideKey() const { return -2 - Side[O].first().entity(); }

  // Where a run arrives at its end (the range from that end inwards): its first vertex
  // off the end's domain point, to tell the line it comes along.
  template <typename It>
  Vec2 arrival(It end, It stop) const
  {
    const Vec2 at = end->domain;
    const double same = slack(1e-9, 1e3) / Size;
    for (It it = end; it != stop; ++it)
      if ((it->domain - at).norm() > 16.0 * same)
        return it->domain;
    return at;
  }

  // The corners the border turns at between two free ends on different sides: where a
  // side of the first end meets a side of the second (one corner), or both meet a third
  // side (two corners), each corner on both sides' segments and a point of the sheet; the
  // shortest such path in P's parameters. A side of P is a segment of its parameters; a
  // side of O is its preimage, a segment when both sides are planar (the map from P's touch
  // to O's is affine). Sides between two faces of one side (smooth edges) are not borders.
  // `arrivals`: where the runs ending at `from` and `to` come from (arrival).
  std::vector<SheetVertex> cornersBetween(const SheetVertex& from, const std::vector<std::pair<int, int>>& a,
    const SheetVertex& to, const std::vector<std::pair<int, int>>& b, const std::array<Vec2, 2>& arrivals) const
  {
    if (Projected || a.empty() || b.empty())
      return {};
    struct Segment
    {
      std::pair<int, int> side;
      Vec2 p0, p1;
    };
    auto segment = [&](const std::pair<int, int>& side, const SheetVertex& near, Segment& out) {
      out.side = side;
      return sideLine(side, near, out.p0, out.p1);
    };
    // Domain points this close are one vertex (as the loop's cleaning has it).
    const double same = slack(1e-9, 1e3) / Size;
    // Where two segments cross, as a sheet point.
    auto meet = [&](const Segment& x, const Segment& y, const SheetVertex& guess, SheetVertex& corner) {
      const Vec2 dx = x.p1 - x.p0, dy = y.p1 - y.p0;
      const double den = dx.x() * dy.y() - dx.y() * dy.x();
      if (std::abs(den) <= 1e-12 * dx.norm() * dy.norm())
        return false;
      const Vec2 w = y.p0 - x.p0;
      const double s = (w.x() * dy.y() - w.y() * dy.x()) / den, t = (w.x() * dx.y() - w.y() * dx.x()) / den;
      // Sides meet at their ends: allow for where the input's rounding put them.
      const double ds = std::max(1e-9, same / dx.norm()), dt = std::max(1e-9, same / dy.norm());
      if (s < -ds || s > 1.0 + ds || t < -dt || t > 1.0 + dt)
        return false;
      // A corner at either end adds nothing (the path would run back along the end's own
      // side, enclosing no area).
      const Vec2 c = x.p0 + s * dx;
      if ((c - from.domain).norm() <= same || (c - to.domain).norm() <= same)
        return false;
      corner = guess;
      if (!solve(c, corner) || !medial(corner))
        return false;
      corner.border = true;
      return true;
    };
    std::vector<Segment> first, last, middle;
    for (const auto& side : a)
      if (Segment g; segment(side, from, g))
        first.push_back(g);
    for (const auto& side : b)
      if (Segment g; segment(side, to, g))
        last.push_back(g);
    SheetVertex guess = from;
    guess.r = 0.5 * (from.r + to.r);
    guess.q[O] = 0.5 * (from.q[O] + to.q[O]);
    for (const auto& side : borderSides())
      if (Segment g; segment(side, guess, g))
        middle.push_back(g);
    // A side of a group of coplanar faces is the sides of several faces in one line: an
    // end's segment goes on through the collinear sides that continue it (the corner where
    // the border turns may lie on another face's part of that line).
    const std::vector<Segment> sides = middle;
    auto extend = [&sides](Segment& g) {
      const double eps = 1e-9;
      for (bool grown = true; grown;)
      {
        grown = false;
        const Vec2 d = g.p1 - g.p0;
        const double length = d.norm();
        if (!(length > 0.0))
          return;
        auto onLine = [&](const Vec2& q) {
          const Vec2 w = q - g.p0;
          return std::abs(d.x() * w.y() - d.y() * w.x()) <= eps * length * (1.0 + w.norm());
        };
        for (const Segment& m : sides)
        {
          if (!onLine(m.p0) || !onLine(m.p1))
            continue;
          const double s0 = (m.p0 - g.p0).dot(d) / (length * length), s1 = (m.p1 - g.p0).dot(d) / (length * length);
          const double lo = std::min(s0, s1), hi = std::max(s0, s1);
          if (lo < -eps && hi >= -eps)
          {
            g.p0 += lo * d;
            grown = true;
            break;
          }
          if (hi > 1.0 + eps && lo <= 1.0 + eps)
          {
            g.p1 = g.p0 + hi * d;
            grown = true;
            break;
          }
        }
      }
    };
    for (auto* list : { &first, &middle, &last })
      for (Segment& g : *list)
        extend(g);
    // Ends on one line of border sides that neither end's run arrives along (the pieces of
    // a surface of revolution side by side, each with its own piece of the line): the
    // border runs straight along it. (A run along the line — a sheet reaching a reflex
    // edge on P's side — closes the other way round.)
    auto onSegment = [same](const Segment& g, const Vec2& q) {
      const Vec2 d = g.p1 - g.p0;
      const double t = d.squaredNorm() > 0.0 ? std::clamp((q - g.p0).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
      return (g.p0 + t * d - q).norm() <= same;
    };
    for (const Segment& g : middle)
      if (onSegment(g, from.domain) && onSegment(g, to.domain) && !onSegment(g, arrivals[0]) &&
        !onSegment(g, arrivals[1]))
        return {};
    std::vector<SheetVertex> best;
    double shortest = std::numeric_limits<double>::infinity();
    auto offer = [&](const std::vector<SheetVertex>& path) {
      double length = 0.0;
      Vec2 at = from.domain;
      for (const SheetVertex& v : path)
      {
        length += (v.domain - at).norm();
        at = v.domain;
      }
      length += (to.domain - at).norm();
      if (length < shortest)
      {
        shortest = length;
        best = path;
      }
    };
    for (const Segment& x : first)
      for (const Segment& y : last)
        if (SheetVertex c; meet(x, y, guess, c))
          offer({ c });
    if (!best.empty())
      return best;
#ifdef EXACTMAT_SHEET_DEBUG
    for (const auto* list : { &first, &middle, &last })
    {
      std::fprintf(stderr, "   %s:", list == &first ? "first" : (list == &last ? "last" : "middle"));
      for (const Segment& g : *list)
        std::fprintf(stderr, " (%d,%d) [%.4g %.4g]-[%.4g %.4g]", g.side.first, g.side.second, g.p0.x(), g.p0.y(), g.p1.x(), g.p1.y());
      std::fprintf(stderr, "\n");
    }
#endif
    // Paths through sides between the ends' own, fewest corners first (the border may
    // follow several sides: around the L-shaped footprint of a tower on a slab it turns
    // three times), the shortest of those. A level keeps, per side, the shortest path that
    // has turned onto it.
    struct Partial
    {
      std::vector<SheetVertex> path;
      double length = std::numeric_limits<double>::infinity();
    };
    std::vector<Partial> level(middle.size());
    for (const Segment& x : first)
      for (size_t m = 0; m < middle.size(); ++m)
      {
        SheetVertex c;
        if (middle[m].side == x.side || !meet(x, middle[m], guess, c))
          continue;
        const double length = (c.domain - from.domain).norm();
        if (length < level[m].length)
          level[m] = Partial{ { c }, length };
      }
    constexpr int MaxCorners = 8;
    for (int corners = 2; corners <= MaxCorners; ++corners)
    {
      bool any = false;
      for (size_t m = 0; m < middle.size(); ++m)
      {
        if (level[m].path.empty())
          continue;
        any = true;
        for (const Segment& y : last)
          if (SheetVertex c; middle[m].side != y.side && meet(middle[m], y, level[m].path.back(), c))
          {
            std::vector<SheetVertex> path = level[m].path;
            path.push_back(c);
            offer(path);
          }
      }
      if (!best.empty() || !any || corners == MaxCorners)
        break;
      std::vector<Partial> next(middle.size());
      for (size_t m = 0; m < middle.size(); ++m)
      {
        if (level[m].path.empty())
          continue;
        const SheetVertex& at = level[m].path.back();
        for (size_t j = 0; j < middle.size(); ++j)
        {
          SheetVertex c;
          if (middle[j].side == middle[m].side || !meet(middle[m], middle[j], at, c) ||
            (c.domain - at.domain).norm() <= same)
            continue;
          const double length = level[m].length + (c.domain - at.domain).norm();
          if (length < next[j].length)
          {
            next[j].path = level[m].path;
            next[j].path.push_back(c);
            next[j].length = length;
          }
        }
      }
      level = std::move(next);
    }
    return best;
  }

  // Every side of the pair's faces that is a border of its side (not a smooth edge
  // between two faces of the same side).
  std::vector<std::pair<int, int>> borderSides() const
  {
    std::vector<std::pair<int, int>> out;
    for (int g : { P, O })
    {
      std::set<int> faces;
      for (const Generator3D* m : Side[g].members())
        if (m->kind() == GeneratorKind3D::Face)
          faces.insert(m->entity());
      for (const Edge3D& e : B.edges())
      {
        const bool a = faces.count(e.faceA) > 0, b = faces.count(e.faceB) > 0;
        if (a && !b)
          out.emplace_back(e.faceA, e.sideA);
        else if (b && !a)
          out.emplace_back(e.faceB, e.sideB);
      }
    }
    if (Side[O].kind() == GeneratorKind3D::ReflexEdge && Side[O].members().size() == 1)
      for (int side = 0; side < 4; ++side)
        out.emplace_back(edgeSideKey(), side);
    return out;
  }

  // Two points of the line a face side (face, patch side) is in P's parameters.
  bool sideLine(const std::pair<int, int>& side, const SheetVertex& near, Vec2& p0, Vec2& p1) const
  {
    if (side.first < -1)
    {
      // A side of the reflex edge O: its ends in the edge's parameters (t, θ).
      const Generator3D& e = Side[O].first();
      const Vec2 ends[4][2] = { { Vec2(0, 0), Vec2(1, 0) }, { Vec2(0, e.edgeAngle(0)), Vec2(1, e.edgeAngle(1)) },
        { Vec2(0, 0), Vec2(0, e.edgeAngle(0)) }, { Vec2(1, 0), Vec2(1, e.edgeAngle(1)) } };
      return side.first == edgeSideKey() && sidePreimage(ends[side.second][0], ends[side.second][1], near, p0, p1);
    }
    const BezierCurve curve = B.faces()[side.first].patch.side(side.second);
    auto onSide = [&side](const SheetSide& s) {
      for (const Generator3D* m : s.members())
        if (m->kind() == GeneratorKind3D::Face && m->entity() == side.first)
          return true;
      return false;
    };
    if (onSide(Side[P]))
    {
      p0 = Side[P].parameterOf(curve.startPoint());
      p1 = Side[P].parameterOf(curve.endPoint());
      return true;
    }
    return onSide(Side[O]) && preimage(curve.startPoint(), near, p0) && preimage(curve.endPoint(), near, p1);
  }

  // P's parameters of the balls touching the reflex edge O at (t, θ) = a and b, the ends
  // of a side of its parameters. An end no ball touching P reaches (the normal of an edge
  // end's fan parallel to P's: a cavity's edge seen from the outer wall it faces away from)
  // is replaced by the farthest point of the side towards it that one does (bisection):
  // the side's line is the same, and balls beyond do not exist.
  bool sidePreimage(const Vec2& a, const Vec2& b, const SheetVertex& near, Vec2& p0, Vec2& p1) const
  {
    auto reach = [&](const Vec2& q, const SheetVertex& from, Vec2& qp, double& r) {
      return preimageOf(Side[O].evaluate(q), from, qp, &r) && r >= -Touch && r <= 4.0 * Size;
    };
    double r0 = 0.0, r1 = 0.0;
    const bool first = reach(a, near, p0, r0), second = reach(b, near, p1, r1);
    if (first == second)
      return first;
    const Vec2 good = first ? a : b, bad = first ? b : a;
    SheetVertex from = near;
    from.q[P] = first ? p0 : p1;
    from.r = first ? r0 : r1;
    Vec2 farthest = from.q[P];
    double lo = 0.0, hi = 1.0;
    for (int k = 0; k < 40; ++k)
    {
      const double mid = 0.5 * (lo + hi);
      Vec2 qp;
      double r = 0.0;
      if (reach(good + mid * (bad - good), from, qp, r))
      {
        lo = mid;
        farthest = qp;
        from.q[P] = qp;
        from.r = r;
      }
      else
        hi = mid;
    }
    if (lo <= 0.0)
      return false;
    (first ? p1 : p0) = farthest;
    return true;
  }

  // P's parameters of the ball that touches O at its point e (along O's normal there).
  bool preimage(const Vec3& e, const SheetVertex& near, Vec2& qp) const
  {
    return preimageOf(Side[O].evaluate(Side[O].parameterOf(e)), near, qp);
  }

  // P's parameters of the ball that touches O as `to` says (point and normal).
  bool preimageOf(const Touch3D& to, const SheetVertex& near, Vec2& qp, double* radius = nullptr) const
  {
    qp = near.q[P];
    double r = near.r;
    for (int it = 0; it < 40; ++it)
    {
      const Touch3D tp = Side[P].evaluate(qp);
      const Vec3 f = tp.point + r * tp.normal - to.point - r * to.normal;
      if (f.norm() <= slack(1e-13, 16.0))
      {
        if (radius)
          *radius = r;
        return true;
      }
      Eigen::Matrix3d j;
      j.col(0) = tp.dPoint.col(0) + r * tp.dNormal.col(0);
      j.col(1) = tp.dPoint.col(1) + r * tp.dNormal.col(1);
      j.col(2) = tp.normal - to.normal;
      const Vec3 d = j.colPivHouseholderQr().solve(-f);
      if (!d.allFinite())
        return false;
      qp += d.head<2>();
      r += d(2);
    }
    return false;
  }

  // The loop with border edges no longer than maxEdge and within the tolerance of the
  // sheet at their middles: sheet points solved on the chords in P's parameters (exact
  // sheet points; on a straight seam between planar faces, exact seam points). Refinement
  // never splits a border edge, so a long or sagging one would leave slivers.
  std::vector<SheetVertex> densified(const std::vector<SheetVertex>& loop) const
  {
    std::vector<SheetVertex> out;
    for (size_t i = 0; i < loop.size(); ++i)
    {
      out.push_back(loop[i]);
      split(loop[i], loop[(i + 1) % loop.size()], 0, out);
    }
    return out;
  }

  // Appends the points strictly between a and b that the border edge needs. An edge
  // between two points of the given curves is a seam's own segment (within the seam's
  // tolerance of the sheet, no longer than its step): kept whole, so the sheets and the
  // seams they share form a conforming complex (a point inserted there would be a
  // T-junction with the seam's polyline).
  void split(const SheetVertex& a, const SheetVertex& b, int depth, std::vector<SheetVertex>& out) const
  {
    if (depth > 16 || (a.source >= 0 && b.source >= 0))
      return;
    SheetVertex m = a;
    m.r = 0.5 * (a.r + b.r);
    m.q[O] = 0.5 * (a.q[O] + b.q[O]);
    if (!solve(0.5 * (a.domain + b.domain), m))
      return;
    const double deviation = std::max((m.x - 0.5 * (a.x + b.x)).norm(), std::abs(m.r - 0.5 * (a.r + b.r)));
    if ((b.x - a.x).norm() <= Options.maxEdge * Size && deviation <= Options.tolerance * Size)
      return;
    m.border = true;
    m.convexEdge = a.convexEdge && b.convexEdge && m.r <= Touch;
    split(a, m, depth + 1, out);
    out.push_back(m);
    split(m, b, depth + 1, out);
  }

  // Two ends on sides of O's curved reflex edge: its parameter domain 0 ≤ θ ≤ α(t),
  // 0 ≤ t ≤ 1 is a quadrilateral, and the border runs round it one way or the other, turning
  // at its corners — the way whose legs' middles are balls of the MAT (the sides' preimages
  // are curves in P's parameters, so their chords cannot tell). The corners on that way.
  bool aroundCurvedEdge(const SheetVertex& from, const SheetVertex& to, std::vector<SheetVertex>& corners) const
  {
    if (Projected || !Options.exact || Side[O].kind() != GeneratorKind3D::ReflexEdge || Side[O].members().size() != 1 ||
      !curvedEdge())
      return false;
    const Generator3D& e = Side[O].first();
    // Corners counter-clockwise (t, θ): (0,0), (1,0), (1,α1), (0,α0); side k runs from
    // corner k to corner k+1: θ = 0, t = 1, θ = α, t = 0.
    const std::array<Vec2, 4> corner{ { Vec2(0, 0), Vec2(1, 0), Vec2(1, e.edgeAngle(1)), Vec2(0, e.edgeAngle(0)) } };
    const double near = slack(1e-7, 1e4) / Size;
    auto sideOf = [&](const Vec2& q) {
      const double value[4] = { q.y(), q.x() - 1.0, q.y() - e.edgeAngle(q.x()), q.x() };
      for (int k = 0; k < 4; ++k)
        if (std::abs(value[k]) <= near)
          return k;
      return -1;
    };
    const int a = sideOf(from.q[O]), b = sideOf(to.q[O]);
    if (a < 0 || b < 0 || a == b)
      return false;
    auto onSheet = [&](const Vec2& q, const SheetVertex& guess, SheetVertex& v) {
      v = guess;
      v.q[O] = q;
      Vec2 qp;
      return preimageOf(Side[O].evaluate(q), guess, qp, &v.r) && solve(qp, v) && medial(v);
    };
    for (int direction : { 1, -1 })
    {
      // Corners passed going from side a to side b.
      std::vector<Vec2> path;
      for (int k = a; k != b; k = (k + direction + 4) % 4)
        path.push_back(corner[direction > 0 ? (k + 1) % 4 : k]);
      std::vector<SheetVertex> found;
      bool ok = true;
      Vec2 last = from.q[O];
      SheetVertex guess = from;
      for (size_t k = 0; k <= path.size() && ok; ++k)
      {
        const Vec2 next = k < path.size() ? path[k] : to.q[O];
        SheetVertex middle, c;
        ok = onSheet(0.5 * (last + next), guess, middle) && (k == path.size() || onSheet(next, middle, c));
        if (ok && k < path.size())
        {
          c.border = true;
          found.push_back(c);
          guess = c;
        }
        last = next;
      }
      if (ok)
      {
        corners = found;
        return true;
      }
    }
    return false;
  }

  // The face owning a face side: P or O (−1 for neither).
  int ownerOf(int face) const
  {
    for (int g : { P, O })
      for (const Generator3D* m : Side[g].members())
        if (m->kind() == GeneratorKind3D::Face && m->entity() == face)
          return g;
    return -1;
  }

  // The shortest chain of curved border sides of one owner's faces from a side in `a` to a
  // side in `b`, consecutive sides sharing an end point (empty when there is none, or when
  // a and b share a side: then no chain is needed).
  std::vector<std::pair<int, int>> curvedSideChain(
    const std::vector<std::pair<int, int>>& a, const std::vector<std::pair<int, int>>& b) const
  {
    std::vector<std::pair<int, int>> sides;
    for (const auto& side : borderSides())
      if (side.first >= 0 && curvedSide(side))
        sides.push_back(side);
    auto index = [&sides](const std::pair<int, int>& side) {
      return static_cast<int>(std::find(sides.begin(), sides.end(), side) - sides.begin());
    };
    auto ends = [this](const std::pair<int, int>& side) {
      const BezierCurve c = B.faces()[side.first].patch.side(side.second);
      return std::array<Vec3, 2>{ { c.startPoint(), c.endPoint() } };
    };
    const int n = static_cast<int>(sides.size());
    std::vector<int> from(n, -2);
    std::vector<int> queue;
    for (const auto& side : a)
      if (const int i = index(side); i < n && from[i] == -2)
      {
        from[i] = -1;
        queue.push_back(i);
      }
    for (size_t q = 0; q < queue.size(); ++q)
    {
      const int i = queue[q];
      if (std::find(b.begin(), b.end(), sides[i]) != b.end())
      {
        std::vector<std::pair<int, int>> chain;
        for (int k = i; k >= 0; k = from[k])
          chain.insert(chain.begin(), sides[k]);
        return chain.size() >= 2 ? chain : std::vector<std::pair<int, int>>{};
      }
      const auto ei = ends(sides[i]);
      for (int j = 0; j < n; ++j)
      {
        if (from[j] != -2 || ownerOf(sides[j].first) != ownerOf(sides[i].first))
          continue;
        const auto ej = ends(sides[j]);
        bool joined = false;
        for (const Vec3& p : ei)
          for (const Vec3& r : ej)
            joined = joined || (p - r).norm() <= Touch;
        if (joined)
        {
          from[j] = i;
          queue.push_back(j);
        }
      }
    }
    return {};
  }

  // The border point where two consecutive sides of a chain meet: the ball touching their
  // common end point along the owner's normal there.
  bool sideJoint(const std::pair<int, int>& s, const std::pair<int, int>& t, const SheetVertex& near, SheetVertex& v) const
  {
    const BezierCurve a = B.faces()[s.first].patch.side(s.second), b = B.faces()[t.first].patch.side(t.second);
    Vec3 joint = a.startPoint();
    double gap = std::numeric_limits<double>::infinity();
    for (const Vec3& p : { a.startPoint(), a.endPoint() })
      for (const Vec3& r : { b.startPoint(), b.endPoint() })
        if ((p - r).norm() < gap)
        {
          gap = (p - r).norm();
          joint = p;
        }
    const int owner = ownerOf(s.first);
    Vec2 qp;
    if (owner == P)
      qp = Side[P].parameterOf(joint);
    else if (owner != O || !preimage(joint, near, qp))
      return false;
    v = near;
    v.q[O] = owner == O ? Side[O].parameterOf(joint) : near.q[O];
    if (!solve(qp, v) || !medial(v))
      return false;
    v.border = true;
    return true;
  }

  // Whether a face side (face, patch side) bends away from its chord.
  bool curvedSide(const std::pair<int, int>& side) const
  {
    const BezierCurve curve = B.faces()[side.first].patch.side(side.second);
    const Vec3 a = curve.startPoint(), d = curve.endPoint() - a;
    for (int i = 1; i < curve.degree(); ++i)
    {
      const Vec3 w = curve.controlPoint(i) - a;
      if ((d.squaredNorm() > 0.0 ? (w - d * (w.dot(d) / d.squaredNorm())).norm() : w.norm()) > Touch)
        return true;
    }
    return false;
  }

  // Whether O (or side g) is a reflex edge that bends away from its chord (a revolved
  // profile's corner).
  bool curvedEdge() const { return curvedEdge(O); }
  bool curvedEdge(int g) const
  {
    const Generator3D& e = Side[g].first();
    const std::vector<int>& f = e.faces();
    if (f.empty())
      return false;
    const Edge3D& edge = B.edges()[e.entity()];
    return curvedSide({ edge.faceA, edge.sideA });
  }

  // Border points from the loop's end to `target` (exclusive at both ends), spaced by
  // maxEdge in space: along the straight line in P's parameters, or along a curved side both
  // ends lie on — the face side `along`, or a side of O's reflex edge when that edge is
  // curved (its normal arc's ends θ = 0, α and its ends t = 0, 1: straight in the edge's
  // parameters, curves in P's) — through its points' preimages in P's parameters, sampled
  // until their chords are within the tolerance.
  void appendGap(std::vector<SheetVertex>& loop, const SheetVertex& target, const std::pair<int, int>& along = { -1, -1 })
  {
    const SheetVertex from = loop.back();
    const double length = (target.x - from.x).norm();
    // guide(f, near): P's parameters of the border at the fraction f of the way (Newton from
    // the border point `near`), and the point whose chords measure the sampling (the touch on
    // the side, or the ball's centre).
    std::function<bool(double, const SheetVertex&, Vec2&, Vec3&)> guide;
    BezierCurve curve;
    if (along.first >= 0 && !Projected)
    {
      int owner = -1;
      curve = B.faces()[along.first].patch.side(along.second);
      for (int g : { P, O })
        for (const Generator3D* m : Side[g].members())
          if (owner < 0 && m->kind() == GeneratorKind3D::Face && m->entity() == along.first)
            owner = g;
      if (owner >= 0)
      {
        const double t0 = closestPoint(curve, from.touch[owner]).t, t1 = closestPoint(curve, target.touch[owner]).t;
        guide = [this, &curve, owner, t0, t1](double f, const SheetVertex& near, Vec2& qp, Vec3& at) {
          at = curve.evaluate((1.0 - f) * t0 + f * t1);
          if (owner == P)
          {
            qp = Side[P].parameterOf(at);
            return true;
          }
          return preimage(at, near, qp);
        };
      }
    }
    // Along a side of O's reflex edge: sampled in the edge's parameters when the edge is
    // curved (every side is a curve in P's parameters), and at its ends t = 0, 1 when it is
    // straight too (the balls touching the end vertex fan its normals: a conic in P's
    // parameters — a circle around a face the edge meets at right angles, as a cavity's edge
    // meets the outer face across the gap; its chord would cut into the vertex's sheet).
    if (!guide && !Projected && Side[O].kind() == GeneratorKind3D::ReflexEdge && Side[O].members().size() == 1)
    {
      const bool curved = curvedEdge();
      const Generator3D& e = Side[O].first();
      const Vec2 a = from.q[O], b = target.q[O];
      const double near = slack(1e-7, 1e4) / Size;
      auto on = [&](const Vec2& q, int side) {
        const double value[4] = { q.y(), q.y() - e.edgeAngle(q.x()), q.x(), q.x() - 1.0 };
        return std::abs(value[side]) <= near;
      };
      // An end of radius 0 is where the edge ends on P: every normal angle's (θ = 0 and
      // θ = α lead there alike).
      auto onEnd = [&](const SheetVertex& v, const Vec2& q, int side) {
        return on(q, side) || (side < 2 && v.r <= Touch && (on(q, 2) || on(q, 3)));
      };
      for (int side = curved ? 0 : 2; side < 4 && !guide; ++side)
        if (onEnd(from, a, side) && onEnd(target, b, side))
          guide = [this, &e, side, a, b](double f, const SheetVertex& near, Vec2& qp, Vec3& at) {
            Vec2 q = (1.0 - f) * a + f * b;
            if (side == 0)
              q.y() = 0.0;
            else if (side == 1)
              q.y() = e.edgeAngle(q.x());
            else
              q.x() = side == 2 ? 0.0 : 1.0;
            const Touch3D to = Side[O].evaluate(q);
            double r = near.r;
            if (!preimageOf(to, near, qp, &r))
              return false;
            at = to.point + r * to.normal;
            return true;
          };
    }
    // The fractions of the way: evenly by maxEdge, or by halving where the guide's chords
    // are longer than maxEdge or off it by more than the tolerance.
    std::vector<double> fractions;
    std::vector<Vec2> guided;
    if (guide)
    {
      std::map<double, std::pair<Vec2, Vec3>> known;
      auto sample = [&](double f) -> const std::pair<Vec2, Vec3>* {
        auto it = known.find(f);
        if (it == known.end())
        {
          // Newton from the nearest point known (the start, at first).
          SheetVertex near = from;
          double gap = f;
          for (const auto& [g, p] : known)
            if (std::abs(g - f) < gap)
            {
              gap = std::abs(g - f);
              near.q[P] = p.first;
            }
          std::pair<Vec2, Vec3> g;
          if (!guide(f, near, g.first, g.second))
            return nullptr;
          it = known.emplace(f, g).first;
        }
        return &it->second;
      };
      std::vector<std::pair<double, double>> todo{ { 0.0, 1.0 } };
      bool ok = true;
      for (int guard = 0; !todo.empty() && guard < 20000 && ok; ++guard)
      {
        const auto [a, b] = todo.back();
        todo.pop_back();
        const auto *pa = sample(a), *pb = sample(b), *pm = sample(0.5 * (a + b));
        ok = pa && pb && pm;
        if (ok && b - a > 1e-6 &&
          ((pb->second - pa->second).norm() > Options.maxEdge * Size ||
            (pm->second - 0.5 * (pa->second + pb->second)).norm() > Options.tolerance * Size))
        {
          todo.push_back({ 0.5 * (a + b), b });
          todo.push_back({ a, 0.5 * (a + b) });
        }
        else if (ok && b < 1.0)
        {
          fractions.push_back(b);
          guided.push_back(pb->first);
        }
      }
      if (!ok)
      {
        fractions.clear();
        guided.clear();
        guide = nullptr;
      }
    }
    if (!guide)
    {
      const int n = std::min(10000, static_cast<int>(std::ceil(length / (Options.maxEdge * Size))));
      for (int k = 1; k < n; ++k)
        fractions.push_back(static_cast<double>(k) / n);
    }
    for (size_t k = 0; k < fractions.size(); ++k)
    {
      const double s = fractions[k];
      // Guesses for the touch on O: the last gap point's (continuation), the straight
      // interpolation of the two ends', and the other end's where one end has radius 0
      // (a reflex edge's angle or a corner's normal means nothing there).
      const Vec2 qp = guide ? guided[k] : Vec2((1.0 - s) * from.domain + s * target.domain);
      const double r = (1.0 - s) * from.r + s * target.r;
      // (A sheet between two reflex entities is solved for both touches: P's is guessed
      // alike, and at radius 0 its angle too means nothing.)
      const SheetVertex& wide = from.r >= target.r ? from : target;
      const std::array<const SheetVertex*, 3> sources{ { &loop.back(), nullptr, &wide } };
      SheetVertex v = from;
      bool solved = false;
      for (size_t g = 0; g < sources.size() && !solved; ++g)
      {
        v = from;
        v.r = r;
        v.x = (1.0 - s) * from.x + s * target.x;
        for (int k : { O, P })
          v.q[k] = sources[g] ? sources[g]->q[k] : Vec2((1.0 - s) * from.q[k] + s * target.q[k]);
        solved = solve(qp, v);
      }
      if (!solved)
        fail("3D MAT sheets: the border of ", name(), " has an open end that cannot be closed along ",
          Side[P].name());
#ifdef EXACTMAT_SHEET_DEBUG
      if (!medial(v))
        std::fprintf(stderr, "  gap point %zu of %zu (guided %d) off the MAT: from q_O (%.6g %.6g) r %.6g to q_O (%.6g %.6g) r %.6g\n", k,
          fractions.size(), (int)static_cast<bool>(guide), from.q[O].x(), from.q[O].y(), from.r, target.q[O].x(), target.q[O].y(), target.r);
#endif
      if (!medial(v))
        fail("3D MAT sheets: closing the border of ", name(), " between two open ends leaves the MAT (at ",
          v.x.transpose(), ")");
      v.border = true;
      loop.push_back(v);
      ++Mesh.gapVertices;
    }
  }

  // Twice the area a loop encloses in P's parameters over its length: its width when it
  // is a sliver.
  static double width(const std::vector<SheetVertex>& loop)
  {
    double twiceArea = 0.0, length = 0.0;
    for (size_t k = 0; k < loop.size(); ++k)
    {
      const Vec2& a = loop[k].domain;
      const Vec2& b = loop[(k + 1) % loop.size()].domain;
      twiceArea += a.x() * b.y() - a.y() * b.x();
      length += (b - a).norm();
    }
    return length > 0.0 ? std::abs(twiceArea) / length : 0.0;
  }

  void triangulate(const std::vector<std::vector<SheetVertex>>& given)
  {
    // A loop narrower than two domain points held apart (out along a line and back: a
    // sheet the tracer lists whose balls all touch one line of P, a face and a cavity wall
    // perpendicular to it seen across a gap) bounds nothing. Exactly on one line it gave no
    // triangles; turned or moved, the rounding made its two sides cross.
    const double same = slack(1e-9, 1e3) / Size;
    std::vector<std::vector<SheetVertex>> loops;
    for (const auto& loop : given)
      if (width(loop) > same)
        loops.push_back(loop);
    if (loops.empty())
    {
      for (const auto& loop : given)
      {
        Mesh.vertices.insert(Mesh.vertices.end(), loop.begin(), loop.end());
        Mesh.loopSizes.push_back(static_cast<int>(loop.size()));
      }
      Mesh.loops = static_cast<int>(given.size());
      return;
    }
    std::vector<std::vector<Vec2>> domain;
    for (const auto& loop : loops)
    {
      domain.emplace_back();
      for (const SheetVertex& v : loop)
      {
        domain.back().push_back(v.domain);
        Mesh.vertices.push_back(v);
      }
    }
    Mesh.loops = static_cast<int>(loops.size());
    for (const auto& loop : loops)
      Mesh.loopSizes.push_back(static_cast<int>(loop.size()));
    std::unique_ptr<DomainTriangulation> t;
    try
    {
      t = std::make_unique<DomainTriangulation>(domain);
    }
    catch (const InputError& e)
    {
      fail("3D MAT sheets: the domain of ", name(), " on ", Side[P].name(), " cannot be triangulated: ", e.what());
    }
    std::set<std::array<int, 3>> accepted;
    double worst = 0.0;
    for (int round = 0; round < 200; ++round)
    {
      int inserted = 0;
      for (const auto& tri : t->triangles())
      {
        std::array<int, 3> key = tri;
        std::sort(key.begin(), key.end());
        if (accepted.count(key))
          continue;
        const SheetVertex& a = Mesh.vertices[tri[0]];
        const SheetVertex& b = Mesh.vertices[tri[1]];
        const SheetVertex& c = Mesh.vertices[tri[2]];
        const double longest = std::max({ (a.x - b.x).norm(), (b.x - c.x).norm(), (c.x - a.x).norm() });
        SheetVertex centroid = a;
        centroid.r = (a.r + b.r + c.r) / 3.0;
        centroid.q[O] = (a.q[O] + b.q[O] + c.q[O]) / 3.0;
        const Vec2 q = (a.domain + b.domain + c.domain) / 3.0;
        if (!solve(q, centroid))
        {
          // The centroid's ball misses O's entity: the domain's border chord cuts outside
          // the exact border there (curved seams). The triangle stays; its vertices are exact.
          accepted.insert(key);
          continue;
        }
        const double deviation =
          std::max((centroid.x - (a.x + b.x + c.x) / 3.0).norm(), std::abs(centroid.r - (a.r + b.r + c.r) / 3.0));
        // A sliver along the border (its centroid about as near the border chord as the
        // chord is to the exact border) is not split further: its centroid would crowd
        // towards a border edge that refinement never splits.
        const double area = 0.5 * (b.x - a.x).cross(c.x - a.x).norm();
        const bool sliver = 2.0 * area / std::max(longest, 1e-300) <= 1e-3 * Options.maxEdge * Size;
        if (sliver || (longest <= Options.maxEdge * Size && deviation <= Options.tolerance * Size))
        {
          accepted.insert(key);
          worst = std::max(worst, deviation);
          continue;
        }
        if (t->insert(q) < 0)
        {
          accepted.insert(key);
          worst = std::max(worst, deviation);
          continue;
        }
        Mesh.vertices.push_back(centroid);
        ++inserted;
        if (static_cast<int>(Mesh.vertices.size()) > Options.maxVertices)
          fail("3D MAT sheets: ", name(), " needs more than ", Options.maxVertices, " vertices");
      }
      if (inserted == 0)
        break;
    }
    Mesh.triangles = t->triangles();
    // Only the final triangles' deviations count.
    worst = 0.0;
    for (const auto& tri : Mesh.triangles)
    {
      const SheetVertex& a = Mesh.vertices[tri[0]];
      const SheetVertex& b = Mesh.vertices[tri[1]];
      const SheetVertex& c = Mesh.vertices[tri[2]];
      SheetVertex centroid = a;
      centroid.r = (a.r + b.r + c.r) / 3.0;
      centroid.q[O] = (a.q[O] + b.q[O] + c.q[O]) / 3.0;
      if (solve((a.domain + b.domain + c.domain) / 3.0, centroid))
      {
        worst = std::max(worst, std::max((centroid.x - (a.x + b.x + c.x) / 3.0).norm(),
                                  std::abs(centroid.r - (a.r + b.r + c.r) / 3.0)));
        Mesh.checkPoints.push_back(centroid);
      }
    }
    Mesh.maxDeviation = worst / Size;
    // Refinement stops at slivers along the border; a sheet still far from the exact one
    // there is parameterised where that degenerates (a rim where the balls touch one
    // point of P whatever their radius): refused, not output approximately.
    if (Mesh.maxDeviation > 10.0 * Options.tolerance)
      fail("3D MAT sheets: the triangles of ", name(), " deviate from the exact sheet by ", Mesh.maxDeviation,
        " of the size (tolerance ", Options.tolerance, "): its parameterisation by ", Side[P].name(),
        " degenerates");
  }
};

} // namespace

std::vector<int> convexEdgesBetween(const Boundary3D& boundary, const std::vector<Generator3D>& generators,
  const SheetGroup& group)
{
  auto faces = [&generators](const std::vector<int>& side) {
    std::set<int> out;
    for (int g : side)
      if (generators[g].kind() == GeneratorKind3D::Face)
        out.insert(generators[g].entity());
    return out;
  };
  const std::set<int> a = faces(group.a), b = faces(group.b);
  std::vector<int> out;
  for (int e = 0; e < static_cast<int>(boundary.edges().size()); ++e)
  {
    const Edge3D& edge = boundary.edges()[e];
    if (edge.kind == VertexKind::Convex &&
      ((a.count(edge.faceA) && b.count(edge.faceB)) || (a.count(edge.faceB) && b.count(edge.faceA))))
      out.push_back(e);
  }
  return out;
}

namespace
{
// Whether side e is one reflex edge or corner of a face of side f (a face side).
bool bordersOwnSide(const std::vector<Generator3D>& generators, const std::vector<int>& f, const std::vector<int>& e)
{
  if (e.size() != 1 || generators[e.front()].kind() == GeneratorKind3D::Face)
    return false;
  for (int g : f)
    if (generators[g].kind() == GeneratorKind3D::Face)
      for (int face : generators[e.front()].faces())
        if (std::find(generators[g].faces().begin(), generators[g].faces().end(), face) != generators[g].faces().end())
          return true;
  return false;
}
} // namespace

std::vector<SheetGroup> groupSheets(const Boundary3D& boundary, const std::vector<Generator3D>& generators,
  const std::vector<std::array<int, 2>>& pairs)
{
  std::map<std::pair<std::vector<int>, std::vector<int>>, int> index;
  std::vector<SheetGroup> out;
  // (Each generator's side once: a revolved solid's pieces are many, each in many pairs.)
  std::map<int, std::vector<int>> sides;
  auto sideOf = [&](int g) -> const std::vector<int>& {
    auto it = sides.find(g);
    if (it == sides.end())
    {
      const std::vector<int> side = sheetSide(boundary, generators, g);
      for (int m : side)
        sides[m] = side;
      it = sides.find(g);
    }
    return it->second;
  };
  for (size_t s = 0; s < pairs.size(); ++s)
  {
    std::vector<int> a = sideOf(pairs[s][0]);
    std::vector<int> b = sideOf(pairs[s][1]);
    if (b < a)
      std::swap(a, b);
    // Two faces of one coplanar group (a degenerate ball on the smooth edge between them,
    // met where a seam crosses it) touch one plane, and so do a group and a reflex edge or
    // corner on its own border: a ball touching both touches them at one point. No sheet.
    if (a == b || bordersOwnSide(generators, a, b) || bordersOwnSide(generators, b, a))
      continue;
    auto [it, added] = index.insert({ { a, b }, static_cast<int>(out.size()) });
    if (added)
      out.push_back({ a, b, {} });
    out[it->second].traced.push_back(static_cast<int>(s));
  }
  // Two faces meeting at a convex edge always have a sheet there, even one no seam
  // borders (its other borders all where it goes on as other pairs' sheets).
  for (const Edge3D& edge : boundary.edges())
  {
    if (edge.kind != VertexKind::Convex)
      continue;
    std::vector<int> a = sideOf(edge.faceA);
    std::vector<int> b = sideOf(edge.faceB);
    if (b < a)
      std::swap(a, b);
    if (a != b && index.insert({ { a, b }, static_cast<int>(out.size()) }).second)
      out.push_back({ a, b, {} });
  }
  return out;
}

MedialSheetMesh interpolateSheet(const Boundary3D& boundary, const std::vector<Generator3D>& generators,
  const std::vector<int>& a, const std::vector<int>& b, const std::vector<SheetBorderCurve>& curves,
  const std::vector<int>& convexEdges, const SheetOptions& options)
{
  auto valid = [&generators](const std::vector<int>& side) {
    for (int g : side)
      if (g < 0 || g >= static_cast<int>(generators.size()))
        return false;
    return !side.empty();
  };
  if (!valid(a) || !valid(b))
    fail("3D MAT sheets: a pair of generators that are not the solid's ", generators.size());
  SheetBuilder builder(boundary, generators, a, b, options);
  if (!builder.curvedEdgePair())
    return builder.build(curves, convexEdges);
  // Between two curved reflex edges: by the first edge's parameters, else the second's
  // (whichever maps the border regularly: a seam can run along one edge's normal fan),
  // else the fitted plane; every one is checked the same way.
  std::string first;
  for (int byEdge : { 0, 1, -1 })
    try
    {
      return SheetBuilder(boundary, generators, a, b, options, byEdge).build(curves, convexEdges);
    }
    catch (const InputError& e)
    {
      if (first.empty())
        first = e.what();
    }
  fail(first, " (nor by the other edge's parameters or a plane fitted to its border)");
}

MedialSheetMesh interpolateSheet(const Boundary3D& boundary, const std::vector<Generator3D>& generators,
  const SheetGroup& group, const std::vector<SheetBorderCurve>& curves, const SheetOptions& options)
{
  const std::vector<int> found = convexEdgesBetween(boundary, generators, group);
  const std::set<int> edges(found.begin(), found.end());
  MedialSheetMesh mesh = interpolateSheet(boundary, generators, group.a, group.b, curves,
    std::vector<int>(edges.begin(), edges.end()), options);
  mesh.traced = group.traced;
  return mesh;
}

std::vector<MedialSheetMesh> interpolateSheets(const Boundary3D& boundary, const MAT3D& mat,
  const SheetOptions& options, std::vector<std::pair<int, std::string>>& failures)
{
  const std::vector<Generator3D> generators = medialGenerators(boundary);
  std::vector<std::array<int, 2>> pairs;
  for (const MAT3DSheet& sheet : mat.sheets)
    pairs.push_back({ { sheet.generatorA, sheet.generatorB } });
  std::vector<SheetGroup> groups = groupSheets(boundary, generators, pairs);
  const PatchBoundary exact(boundary);
  SheetOptions checked = options;
  if (!checked.exact)
    checked.exact = &exact;
  // The cone sheets at the centre curves' ends, each whole (the groups from its convex
  // edges are parts of it).
  std::vector<MedialSheetMesh> caps;
  std::vector<std::string> capErrors;
  for (const CapEnd& end : capEnds(mat, boundary, generators))
  {
    capErrors.emplace_back();
    try
    {
      caps.push_back(interpolateCapSheet(boundary, generators, end, checked));
    }
    catch (const InputError& e)
    {
      capErrors.back() = e.what();
      caps.emplace_back();
    }
  }
  dropCapGroups(groups, caps);
  std::vector<MedialSheetMesh> out;
  std::vector<std::vector<SheetBorderCurve>> borders;
  std::vector<std::string> errors;
  for (const SheetGroup& group : groups)
  {
    std::vector<SheetBorderCurve> curves;
    std::set<int> seams;
    for (int s : group.traced)
      seams.insert(mat.sheets[s].seams.begin(), mat.sheets[s].seams.end());
    for (int k : seams)
    {
      SheetBorderCurve curve;
      const std::vector<MedialBall3D>& balls = mat.seams[k].balls;
      for (size_t i = 0; i < balls.size(); ++i)
      {
        curve.centres.push_back(balls[i].x);
        curve.radii.push_back(balls[i].r);
        curve.ids.push_back(static_cast<int>(i));
      }
      curves.push_back(std::move(curve));
    }
    errors.emplace_back();
    try
    {
      out.push_back(interpolateSheet(boundary, generators, group, curves, checked));
    }
    catch (const InputError& e)
    {
      errors.back() = e.what();
      out.emplace_back();
      out.back().generators = { { group.a.front(), group.b.front() } };
      out.back().members = { { group.a, group.b } };
      out.back().traced = group.traced;
    }
    borders.push_back(std::move(curves));
  }
  // Sheets no seam borders, found beyond the borders of those built.
  addTransitionSheets(boundary, generators, groups, borders, out, errors, checked);
  // A MAT with no seam: each closed rim bounds a sheet of its own (the ellipsoid's).
  for (const SheetBorderCurve& rim : seamlessRims(mat))
  {
    errors.emplace_back();
    try
    {
      out.push_back(interpolateRimSheet(boundary, generators, rim, checked));
    }
    catch (const InputError& e)
    {
      errors.back() = e.what();
      out.emplace_back();
    }
  }
  for (size_t k = 0; k < caps.size(); ++k)
  {
    out.push_back(std::move(caps[k]));
    errors.push_back(capErrors[k]);
  }
  for (size_t k = 0; k < errors.size(); ++k)
    if (!errors[k].empty())
      failures.emplace_back(static_cast<int>(k), errors[k]);
  return out;
}

} // namespace exactmat
