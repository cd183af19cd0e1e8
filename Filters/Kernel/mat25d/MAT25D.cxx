#include "MAT25D.h"

#include "common/Format.h"
#include "common/InputError.h"
#include "mat2d/Bisector.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <sstream>

namespace exactmat
{

namespace
{
bool anyContinuum(const std::vector<BoundaryLocation>& fps)
{
  return std::any_of(fps.begin(), fps.end(), [](const BoundaryLocation& f) { return f.continuum; });
}

/// One column of a profile sheet: from footpoint `foot` (radius 0) to MAT point `x`
/// (radius r), whose point on the seam is `top`.
struct StripColumn
{
  Vec2 foot, x;
  double r = 0.0;
  int top = -1;       ///< the column's last point: on a seam (or the truncation point)
  double tTop = 1.0;  ///< where the column ends on F → x (< 1: at the mid-surface)
  int midTop = -1;    ///< above the mid-surface: the point T_{S/2}(x) the mid-sheet reaches
};

class Builder
{
public:
  Builder(const Generators& g, const MedialGraph& m, const SweepMap& w, const MAT25DOptions& o)
    : G(g)
    , M(m)
    , W(w)
    , O(o)
    , E(static_cast<int>(g.boundary().edges().size()))
  {
  }

  MedialComplex run()
  {
    if (M.nodes.empty())
      fail("2.5D MAT: the profile's 2D MAT is empty");
    S = W.span();
    chooseResolution();
    NodeColumn.resize(M.nodes.size());
    NodeMid.assign(M.nodes.size(), -1);
    for (size_t n = 0; n < M.nodes.size(); ++n)
      buildNode(static_cast<int>(n));
    const size_t total = M.segments.size();
    for (size_t k = 0; k < total; ++k)
    {
      buildSegment(static_cast<int>(k));
      if (O.progress)
        O.progress(static_cast<double>(k + 1) / static_cast<double>(total));
    }
    // Sheets built strip by strip meet along footpoint normals and at nodes: one vertex
    // there, so the output is a connected complex.
    C.weld(1e-12 * Fine);
    // The seams keep every sample, the sheets only columns about SheetResolution apart:
    // the sheets' border triangles are fanned through the seams' points in between.
    C.fanSheetsToCurves();
    return std::move(C);
  }

private:
  void chooseResolution()
  {
    double rhoMax = 0.0;
    for (const Edge2D& e : G.boundary().edges())
    {
      for (int i = 0; i <= e.curve.degree(); ++i)
      {
        const Vec3 c = e.curve.controlPoint(i);
        rhoMax = std::max(rhoMax, W.axisDistance(Vec2(c.x(), c.y())));
      }
    }
    const double sweepLength = W.kind() == SweepKind::Extrusion ? S : S * rhoMax;
    Size = std::max(G.size2D(), sweepLength);
    // The smaller extent sets what is distinct: an extrusion 1e-12 long (or 1e12 long,
    // for the profile) has points 1e-12 of the larger one apart that are not the same.
    Fine = std::min(G.size2D(), sweepLength);
    const double h = std::max(1e-6, O.sheetResolution) * Size;
    Across = std::clamp(static_cast<int>(std::ceil(sweepLength / h)), 4, 4096);
    if (W.closed())
      Across = std::max(Across, 24);
    Levels = std::clamp(static_cast<int>(std::ceil(M.maximumRadius() / h)), 2, 1024);
  }

  int addPoint(const Vec3& x, double r, MedialPoint3DType type, int contacts)
  {
    MedialPoint3D p;
    p.x = x;
    p.radius = r;
    p.type = type;
    p.contacts = contacts;
    C.points.push_back(std::move(p));
    return static_cast<int>(C.points.size()) - 1;
  }

  /// The points T_τ(p) across the sweep: τ from capSpan to S − capSpan (Across + 1
  /// points, the ends typed as `capType`) or, closed, the Across points of the full turn.
  std::vector<int> column(const Vec2& p, double r, MedialPoint3DType capType, int capContacts,
    MedialPoint3DType type, int contacts)
  {
    std::vector<int> ids;
    if (W.closed())
    {
      for (int j = 0; j < Across; ++j)
        ids.push_back(addPoint(W.place(p, S * j / Across), r, type, contacts));
      return ids;
    }
    const double t0 = W.capSpan(p, r), t1 = S - t0;
    if (t1 - t0 <= 1e-12 * S)
    {
      // Both seams meet (span = 2·capSpan): one point touching both profile faces, a
      // degenerate seam or junction point (§5.5.1).
      const int id = addPoint(W.place(p, 0.5 * S), r, capType, capContacts > 0 ? capContacts + 1 : 0);
      return std::vector<int>(Across + 1, id);
    }
    for (int j = 0; j <= Across; ++j)
    {
      const bool cap = j == 0 || j == Across;
      const double tau = j == Across ? t1 : t0 + (t1 - t0) * j / Across;
      ids.push_back(addPoint(W.place(p, tau), r, cap ? capType : type, cap ? capContacts : contacts));
    }
    return ids;
  }

  /// Only the two seam points of T_τ(p) (a sample between sheet columns).
  std::vector<int> seamPoints(const Vec2& p, double r)
  {
    const double t0 = W.capSpan(p, r), t1 = S - t0;
    if (t1 - t0 <= 1e-12 * S)
    {
      const int id = addPoint(W.place(p, 0.5 * S), r, MedialPoint3DType::Seam, 4);
      return { id, id };
    }
    return { addPoint(W.place(p, t0), r, MedialPoint3DType::Seam, 3),
      addPoint(W.place(p, t1), r, MedialPoint3DType::Seam, 3) };
  }

  void buildNode(int n)
  {
    const MedialNode& node = M.nodes[n];
    // A disk touching a whole arc (its centre) has no finite number of touchpoints.
    const bool continuum = anyContinuum(node.footpoints) ||
      (node.sample.radius > 0.0 &&
        anyContinuum(G.footpointsWithin(node.sample.x, node.sample.radius * (1.0 + 1e-9))));
    const int feet = continuum ? 0 : static_cast<int>(node.footpoints.size());
    const Vec2& x = node.sample.x;
    const double r = node.sample.radius;
    using T = MedialPoint3DType;
    std::vector<int> govs = governors(node.footpoints);
    if (station(x, r) == Station::Above)
    {
      // Inside the mid-sheet: the ball meets both profile faces first; no junction, seam
      // or skeletal edge comes from this node (its point is the mid-sheet's, nodeMid).
      if (node.type == MedialPointType::CircleCentre)
        circleProfileSheets(n);
      return;
    }
    switch (node.type)
    {
      case MedialPointType::Branch:
        NodeColumn[n] = column(x, r, T::Junction, feet > 0 ? feet + 1 : 0, T::Seam, feet);
        addCurve(MedialElementType::Seam, NodeColumn[n], govs, n);
        if (!W.closed())
        {
          if (NodeColumn[n].back() == NodeColumn[n].front())
            addJunction(NodeColumn[n].front(), govs, { E, E + 1 }, n); // span = 2·r: both faces
          else
          {
            addJunction(NodeColumn[n].front(), govs, { E }, n);
            addJunction(NodeColumn[n].back(), govs, { E + 1 }, n);
          }
        }
        break;
      case MedialPointType::ConvexVertexEnd:
        NodeColumn[n] = column(x, 0.0, T::SeamEnd, 0, T::ConvexEdge, 0);
        break;
      case MedialPointType::CurvatureCentreEnd:
        NodeColumn[n] = column(x, r, T::SeamEnd, feet > 0 ? 2 : 0, T::SkeletalEdge, feet > 0 ? 1 : 0);
        addCurve(MedialElementType::SkeletalEdge, NodeColumn[n], govs, n);
        break;
      case MedialPointType::CircleCentre:
        NodeColumn[n] = column(x, r, T::CircleCentre, 0, T::CircleCentre, 0);
        addCurve(MedialElementType::CentreCurve, NodeColumn[n], govs, n);
        if (!W.closed())
          circleProfileSheets(n);
        break;
      case MedialPointType::Normal:
      case MedialPointType::CycleJoint:
        NodeColumn[n] = column(x, r, T::Seam, 3, T::Sheet, 2);
        break;
    }
  }

  /// A junction vertex; `faces` are the profile faces its ball touches.
  void addJunction(int id, std::vector<int> govs, std::initializer_list<int> faces, int n)
  {
    govs.insert(govs.begin(), faces);
    MedialElement e;
    e.type = MedialElementType::Junction;
    e.points = { id };
    e.governors = std::move(govs);
    e.profileSegment = n;
    C.elements.push_back(std::move(e));
  }

  // A polyline across the sweep (closed into a circle for 360° revolutions).
  void addCurve(MedialElementType type, const std::vector<int>& ids, std::vector<int> govs, int source)
  {
    MedialElement e;
    e.type = type;
    e.points = ids;
    if (W.closed())
      e.points.push_back(ids.front());
    e.points.erase(std::unique(e.points.begin(), e.points.end()), e.points.end());
    if (e.points.size() < 2)
      return; // a degenerate column: its point is a junction already
    e.governors = std::move(govs);
    e.profileSegment = source;
    C.elements.push_back(std::move(e));
  }

  // Where a profile MAT point lies relative to the mid-surface between the profile faces
  // (the bisector of the two faces: τ = S/2). Above it (spans shorter than 2·capSpan) the
  // ball meets both profile faces before it could reach its 2D radius.
  enum class Station
  {
    Below,    ///< 2·capSpan < S: the thesis' case
    Crossing, ///< 2·capSpan = S: a junction touching both faces and two sides
    Above     ///< 2·capSpan > S: inside the mid-sheet
  };

  Station station(const Vec2& p, double r) const
  {
    if (W.closed())
      return Station::Below;
    const double d = 2.0 * W.capSpan(p, r) - S;
    return d > 1e-12 * S ? Station::Above : (d >= -1e-12 * S ? Station::Crossing : Station::Below);
  }

  /// The radius of the ball about T_{S/2}(p) touching both profile faces.
  double midRadius(const Vec2& p) const
  {
    return W.kind() == SweepKind::Extrusion ? 0.5 * S : W.axisDistance(p) * std::sin(0.5 * S);
  }

  /// Where the segment from footpoint F (radius 0) to MAT point x (radius r) meets the
  /// mid-surface: t with t·r = midRadius(F + t(x − F)) (midRadius is affine in p).
  double truncation(const Vec2& foot, const Vec2& x, double r) const
  {
    const double m0 = midRadius(foot), m1 = midRadius(x);
    const double t = m0 / (r - (m1 - m0));
    return std::clamp(t, 0.0, 1.0);
  }

  /// The MAT point between samples p (below) and q (above) whose ball touches both profile
  /// faces: on the pair's bisector with r = midRadius(x) (Bisector::correct inside a
  /// bracketed secant from p to q); an InputError when no generator pair solves it.
  MedialSample crossing(const MedialSample& p, const MedialSample& q) const
  {
    // The generators may change between the samples (a front passing a smooth vertex or
    // onto a corner): try p's pair, then q's.
    MedialSample c;
    if (crossingOnPair(p, q, p, c) || crossingOnPair(p, q, q, c))
      return c;
    // No silent approximation: a junction that cannot be solved exactly is an error.
    fail("2.5D MAT: the junction where the profile's MAT crosses the mid-surface between ",
      "the profile faces (between MAT points ", format(Vec3(p.x.x(), p.x.y(), 0.0)), " and ",
      format(Vec3(q.x.x(), q.x.y(), 0.0)), ", generators ", p.foot[0].g, " and ", p.foot[1].g,
      ") could not be solved; a slightly different span avoids it");
  }

  bool crossingOnPair(
    const MedialSample& p, const MedialSample& q, const MedialSample& pair, MedialSample& c) const
  {
    // A secant on w ∈ [0,1] from p to q: the unknowns are interpolated, then corrected onto
    // the bisector with one of them held; which one may be held depends on the segment (r
    // is constant between parallel edges, a footpoint can rest on a corner), so each is
    // tried in turn.
    for (int fixed = 0; fixed < 3; ++fixed)
      if (crossingOnPair(p, q, pair, fixed, c))
        return true;
    return false;
  }

  bool crossingOnPair(const MedialSample& p, const MedialSample& q, const MedialSample& pair,
    int fixed, MedialSample& c) const
  {
    const int ga = pair.foot[0].g, gb = pair.foot[1].g;
    const Bisector bisector(G, ga, gb);
    // A sample whose front has moved on to the neighbour of the pair's generator is at
    // that generator's end (front a moves forward, b backward): interpolating from there
    // keeps the first guess on the branch of the bisector between the samples (the
    // bisector of two pieces meeting at a smooth vertex has others, with empty disks
    // nowhere near).
    auto start = [&](const MedialSample& m, int k) {
      const int g = pair.foot[k].g;
      if (m.foot[k].g == g)
        return m.foot[k].s;
      if (m.foot[k].g == G[g].next)
        return 1.0;
      if (m.foot[k].g == G[g].prev)
        return 0.0;
      return pair.foot[k].s;
    };
    auto solve = [&](double w, BisectorState& y) {
      y = { start(p, 0) + w * (start(q, 0) - start(p, 0)), start(p, 1) + w * (start(q, 1) - start(p, 1)),
        p.radius + w * (q.radius - p.radius) };
      if (!bisector.correct(y, fixed, 1e-15 * G.size2D()))
        return std::numeric_limits<double>::quiet_NaN();
      return y.r - midRadius(bisector.point(y));
    };
    double lo = 0.0, hi = 1.0;
    double flo = p.radius - midRadius(p.x), fhi = q.radius - midRadius(q.x);
    BisectorState y;
    bool converged = false;
    for (int it = 0; it < 100 && !converged; ++it)
    {
      double w = (fhi != flo) ? lo - flo * (hi - lo) / (fhi - flo) : 0.5 * (lo + hi);
      if (!(w > lo && w < hi))
        w = 0.5 * (lo + hi);
      const double f = solve(w, y);
      if (std::isnan(f))
        return false;
      converged = std::abs(f) <= 1e-14 * Fine || hi - lo <= 1e-15;
      if ((f < 0.0) == (flo < 0.0))
      {
        lo = w;
        flo = f;
        fhi *= 0.5; // Illinois: keep the stale end from stalling the secant
      }
      else
      {
        hi = w;
        fhi = f;
        flo *= 0.5;
      }
    }
    // A solution past a generator's end belongs to the other pair (the curve beyond its
    // end is not the boundary).
    if (!converged || y.sa < 0.0 || y.sa > 1.0 || y.sb < 0.0 || y.sb > 1.0 ||
      std::abs(y.r - midRadius(bisector.point(y))) > 1e-12 * Fine + 1e-14 * G.size2D())
      return false;
    // On the MAT only if its disk is empty (another branch of the pair's bisector is not).
    if (G.anyCloserThan(bisector.point(y), y.r * (1.0 - 1e-12) - 1e-13 * G.size2D()))
      return false;
    c.x = bisector.point(y);
    c.radius = y.r;
    const double s[2] = { y.sa, y.sb };
    const int g[2] = { ga, gb };
    for (int k = 0; k < 2; ++k)
    {
      const GeneratorPoint e = G.evaluate(g[k], s[k]);
      c.foot[k].g = g[k];
      c.foot[k].s = s[k];
      c.foot[k].point = e.p;
      c.foot[k].normal = e.n;
    }
    return true;
  }

  void buildSegment(int k)
  {
    const MedialSegment& seg = M.segments[k];
    // Samples that repeat their predecessor or the end node (a tracer's first step can
    // land on its node) would be a second, mislabelled copy of that point. Where the
    // segment passes the mid-surface, the crossing point is inserted.
    const double same = 1e-12 * Fine;
    std::vector<MedialSample> samples{ seg.samples.front() };
    std::vector<Station> kind{ station(seg.samples.front().x, seg.samples.front().radius) };
    std::vector<bool> inserted{ false }; ///< crossings found between two samples
    for (size_t i = 1; i < seg.samples.size(); ++i)
    {
      const MedialSample& x = seg.samples[i];
      const bool last = i + 1 == seg.samples.size();
      if (!last && ((x.x - samples.back().x).norm() <= same || (x.x - seg.samples.back().x).norm() <= same))
        continue;
      const Station st = station(x.x, x.radius);
      if ((st == Station::Above && kind.back() == Station::Below) ||
        (st == Station::Below && kind.back() == Station::Above))
      {
        samples.push_back(st == Station::Above ? crossing(samples.back(), x) : crossing(x, samples.back()));
        kind.push_back(Station::Crossing);
        inserted.push_back(true);
      }
      samples.push_back(x);
      kind.push_back(st);
      inserted.push_back(false);
    }
    const size_t n = samples.size();
    // Every sample gives seam points; sheets take columns about SheetResolution apart (a
    // fixed 1e-3 step would otherwise make a hundred thousand sheet points of a box).
    std::vector<bool> sheetColumn(n, false);
    sheetColumn.front() = sheetColumn.back() = true;
    const double spacing = std::max(1e-6, O.sheetResolution) * Size;
    double travelled = 0.0;
    for (size_t i = 1; i + 1 < n; ++i)
    {
      travelled += (samples[i].x - samples[i - 1].x).norm();
      const double ahead = (samples.back().x - samples[i].x).norm();
      if (kind[i] == Station::Crossing || kind[i] != kind[i - 1] || kind[i] != kind[i + 1] ||
        (travelled >= spacing && ahead >= 0.5 * spacing))
      {
        sheetColumn[i] = true;
        travelled = 0.0;
      }
    }
    std::vector<std::vector<int>> columns(n);
    std::vector<int> mid(n, -1); // above: the point T_{S/2}(x); crossing: the junction
    for (size_t i = 0; i < n; ++i)
    {
      const MedialSample& s = samples[i];
      const bool node = i == 0 || i + 1 == n;
      const int nodeId = i == 0 ? seg.startNode : seg.endNode;
      if (kind[i] == Station::Above)
      {
        mid[i] = node ? nodeMid(nodeId) : addPoint(W.place(s.x, 0.5 * S), midRadius(s.x), MedialPoint3DType::Sheet, 2);
        continue;
      }
      if (node)
        columns[i] = NodeColumn[nodeId];
      else if (inserted[i])
      {
        const int id = addPoint(W.place(s.x, 0.5 * S), s.radius, MedialPoint3DType::Junction, 4);
        columns[i].assign(Across + 1, id);
        addJunction(id, governors({ s.foot[0], s.foot[1] }), { E, E + 1 }, k);
      }
      else if (sheetColumn[i] || kind[i] == Station::Crossing)
        columns[i] = column(s.x, s.radius, MedialPoint3DType::Seam, 3, MedialPoint3DType::Sheet, 2);
      else if (!W.closed())
        columns[i] = seamPoints(s.x, s.radius);
      if (kind[i] == Station::Crossing)
        mid[i] = columns[i].front();
    }
    std::vector<BoundaryLocation> sideA, sideB;
    for (const MedialSample& s : samples)
    {
      sideA.push_back(s.foot[0]);
      sideB.push_back(s.foot[1]);
    }
    const std::vector<int> govA = governors(sideA), govB = governors(sideB);
    std::vector<int> govAB = govA;
    govAB.insert(govAB.end(), govB.begin(), govB.end());
    std::sort(govAB.begin(), govAB.end());
    govAB.erase(std::unique(govAB.begin(), govAB.end()), govAB.end());

    // The swept sheet between the seams, where the segment is below the mid-surface.
    MedialElement sheet;
    sheet.type = MedialElementType::SweptSheet;
    sheet.governors = govAB;
    sheet.profileSegment = k;
    for (size_t i = 0, next = 1; next < n; i = next++)
    {
      while (!sheetColumn[next])
        ++next;
      if (columns[i].empty() || columns[next].empty())
        continue;
      const int rows = static_cast<int>(columns[i].size());
      for (int j = 0; j < (W.closed() ? rows : rows - 1); ++j)
      {
        const int j1 = (j + 1) % rows;
        quad(sheet, columns[i][j], columns[next][j], columns[next][j1], columns[i][j1]);
      }
    }
    if (!sheet.triangles.empty())
      C.elements.push_back(std::move(sheet));
    if (W.closed())
      return;

    // The seams on both profile faces (broken where the segment is above the mid-surface).
    for (int face = 0; face < 2; ++face)
    {
      std::vector<int> govs = govAB;
      govs.insert(govs.begin(), E + face);
      std::vector<int> seam;
      for (size_t i = 0; i <= n; ++i)
      {
        if (i < n && !columns[i].empty())
        {
          seam.push_back(face == 0 ? columns[i].front() : columns[i].back());
          continue;
        }
        addPolyline(MedialElementType::Seam, seam, govs, k);
        seam.clear();
      }
    }
    // Per side: the profile sheets below both faces, the mid-sheet and its seam (the seam
    // through every sample above the mid-surface, the sheets through the sheet columns).
    for (int side = 0; side < 2; ++side)
    {
      std::vector<int> midGovs = side == 0 ? govA : govB;
      midGovs.insert(midGovs.begin(), { E, E + 1 });
      std::vector<StripColumn> strip;
      std::vector<int> midSeam;
      for (size_t i = 0; i <= n; ++i)
      {
        if (i == n || kind[i] == Station::Below)
        {
          addPolyline(MedialElementType::Seam, midSeam, midGovs, k);
          midSeam.clear();
        }
        if (i == n)
          break;
        const MedialSample& s = samples[i];
        StripColumn c{ s.foot[side].point, s.x, s.radius, -1 };
        if (kind[i] == Station::Above)
        {
          c.tTop = truncation(c.foot, c.x, c.r);
          const Vec2 t = c.foot + c.tTop * (c.x - c.foot);
          c.top = addPoint(W.place(t, 0.5 * S), c.tTop * c.r, MedialPoint3DType::Seam, 3);
          c.midTop = mid[i];
          midSeam.push_back(c.top);
        }
        else if (kind[i] == Station::Crossing)
        {
          c.top = c.midTop = mid[i];
          midSeam.push_back(c.top);
        }
        if (sheetColumn[i])
          strip.push_back(c);
      }
      for (int face = 0; face < 2; ++face)
      {
        std::vector<int> sg = side == 0 ? govA : govB;
        sg.insert(sg.begin(), E + face);
        std::vector<StripColumn> faceStrip = strip;
        for (size_t i = 0, j = 0; i < n; ++i)
        {
          if (!sheetColumn[i])
            continue;
          if (kind[i] == Station::Below)
            faceStrip[j].top = face == 0 ? columns[i].front() : columns[i].back();
          ++j;
        }
        profileSheet(face, faceStrip, sg, k);
      }
      midSheet(strip, midGovs, k);
    }
  }

  /// The point T_{S/2}(x) of a node above the mid-surface, shared by its segments.
  int nodeMid(int n)
  {
    if (NodeMid[n] < 0)
      NodeMid[n] = addPoint(W.place(M.nodes[n].sample.x, 0.5 * S), midRadius(M.nodes[n].sample.x),
        MedialPoint3DType::Sheet, 2);
    return NodeMid[n];
  }

  // The mid-sheet (equidistant to both profile faces) over the strip's upper parts: from
  // the truncation point T to the MAT point x, at τ = S/2, radius midRadius.
  void midSheet(const std::vector<StripColumn>& strip, std::vector<int> govs, int k)
  {
    std::vector<std::vector<int>> cols(strip.size());
    for (size_t i = 0; i < strip.size(); ++i)
    {
      const StripColumn& c = strip[i];
      if (c.midTop < 0)
        continue;
      if (c.tTop >= 1.0)
      {
        cols[i].assign(Levels + 1, c.midTop);
        continue;
      }
      cols[i].push_back(c.top);
      for (int q = 1; q < Levels; ++q)
      {
        const double t = c.tTop + (1.0 - c.tTop) * q / Levels;
        const Vec2 p = c.foot + t * (c.x - c.foot);
        cols[i].push_back(addPoint(W.place(p, 0.5 * S), midRadius(p), MedialPoint3DType::Sheet, 2));
      }
      cols[i].push_back(c.midTop);
    }
    MedialElement sheet;
    sheet.type = MedialElementType::MidSheet;
    sheet.governors = std::move(govs);
    sheet.profileSegment = k;
    for (size_t i = 0; i + 1 < cols.size(); ++i)
    {
      if (cols[i].empty() || cols[i + 1].empty())
        continue;
      for (int q = 0; q < Levels; ++q)
        quad(sheet, cols[i][q], cols[i + 1][q], cols[i + 1][q + 1], cols[i][q + 1]);
    }
    if (!sheet.triangles.empty())
      C.elements.push_back(std::move(sheet));
  }

  void addPolyline(MedialElementType type, std::vector<int> ids, std::vector<int> govs, int k)
  {
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    if (ids.size() < 2)
      return;
    MedialElement e;
    e.type = type;
    e.points = std::move(ids);
    e.governors = std::move(govs);
    e.profileSegment = k;
    C.elements.push_back(std::move(e));
  }

  // The sheet between profile face `face` and one side, over the strip of segments from
  // footpoints to MAT points: T_τ(F + t(x − F)), radius t·r, τ = capSpan (face 0) or
  // S − capSpan (face 1).
  void profileSheet(int face, const std::vector<StripColumn>& strip, std::vector<int> govs, int k)
  {
    std::vector<std::vector<int>> cols(strip.size());
    int previousFootId = -1;
    Vec2 previousFoot(NaN, NaN);
    for (size_t i = 0; i < strip.size(); ++i)
    {
      const StripColumn& c = strip[i];
      std::vector<int>& ids = cols[i];
      if (c.r <= 0.0 && (c.x - c.foot).norm() <= 1e-15 * G.size2D())
      {
        ids.assign(Levels + 1, c.top); // a convex vertex: the column is one point
        previousFootId = -1;
        continue;
      }
      // Footpoints repeat along a reflex corner: one boundary point.
      const bool sameFoot = previousFootId >= 0 && (c.foot - previousFoot).norm() <= 1e-15 * G.size2D();
      const int footId = sameFoot ? previousFootId
                                  : addPoint(W.place(c.foot, face == 0 ? 0.0 : S), 0.0,
                                      MedialPoint3DType::ConvexEdge, 0);
      previousFootId = footId;
      previousFoot = c.foot;
      ids.push_back(footId);
      for (int q = 1; q < Levels; ++q)
      {
        const double t = c.tTop * q / Levels;
        const Vec2 p = c.foot + t * (c.x - c.foot);
        const double r = t * c.r;
        const double span = W.capSpan(p, r);
        ids.push_back(addPoint(W.place(p, face == 0 ? span : S - span), r, MedialPoint3DType::Sheet, 2));
      }
      ids.push_back(c.top);
    }
    MedialElement sheet;
    sheet.type = MedialElementType::ProfileSheet;
    sheet.governors = std::move(govs);
    sheet.profileSegment = k;
    for (size_t i = 0; i + 1 < cols.size(); ++i)
    {
      for (int q = 0; q < Levels; ++q)
      {
        if (face == 0)
          quad(sheet, cols[i][q], cols[i + 1][q], cols[i + 1][q + 1], cols[i][q + 1]);
        else
          quad(sheet, cols[i][q], cols[i][q + 1], cols[i + 1][q + 1], cols[i + 1][q]);
      }
    }
    if (!sheet.triangles.empty())
      C.elements.push_back(std::move(sheet));
  }

  // A circular profile: its profile sheets are cones from the circle to the centre
  // (truncated at the mid-surface, with a mid-sheet disk, when the span is short).
  void circleProfileSheets(int n)
  {
    const MedialNode& node = M.nodes[n];
    const double h = std::max(1e-6, O.sheetResolution) * Size;
    const bool above = station(node.sample.x, node.sample.radius) == Station::Above;
    for (const BoundaryLocation& f : node.footpoints)
    {
      double length = 0.0;
      Vec2 last = G.evaluate(f.g, 0.0).p;
      for (int i = 1; i <= 16; ++i)
      {
        const Vec2 p = G.evaluate(f.g, i / 16.0).p;
        length += (p - last).norm();
        last = p;
      }
      const int count = std::clamp(static_cast<int>(std::ceil(length / h)), 4, 4096);
      std::vector<StripColumn> strip;
      for (int i = 0; i <= count; ++i)
      {
        StripColumn c{ G.evaluate(f.g, static_cast<double>(i) / count).p, node.sample.x,
          node.sample.radius, -1 };
        if (above)
        {
          c.tTop = truncation(c.foot, c.x, c.r);
          const Vec2 t = c.foot + c.tTop * (c.x - c.foot);
          c.top = addPoint(W.place(t, 0.5 * S), c.tTop * c.r, MedialPoint3DType::Seam, 3);
          c.midTop = nodeMid(n);
        }
        strip.push_back(c);
      }
      const int g = governorOfGenerator(G, f.g);
      for (int face = 0; face < 2; ++face)
      {
        std::vector<StripColumn> faceStrip = strip;
        if (!above)
          for (StripColumn& c : faceStrip)
            c.top = face == 0 ? NodeColumn[n].front() : NodeColumn[n].back();
        profileSheet(face, faceStrip, { E + face, g }, n);
      }
      if (above)
      {
        midSheet(strip, { E, E + 1, g }, n);
        std::vector<int> seam;
        for (const StripColumn& c : strip)
          seam.push_back(c.top);
        addPolyline(MedialElementType::Seam, seam, { E, E + 1, g }, n);
      }
    }
  }

  static void quad(MedialElement& e, int a, int b, int c, int d)
  {
    triangle(e, a, b, c);
    triangle(e, a, c, d);
  }
  static void triangle(MedialElement& e, int a, int b, int c)
  {
    if (a != b && b != c && a != c)
      e.triangles.push_back({ a, b, c });
  }

  std::vector<int> governors(const std::vector<BoundaryLocation>& fps) const
  {
    std::vector<int> out;
    for (const BoundaryLocation& f : fps)
      if (f.g >= 0)
        out.push_back(governorOfGenerator(G, f.g));
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }

  const Generators& G;
  const MedialGraph& M;
  const SweepMap& W;
  const MAT25DOptions& O;
  const int E;
  double S = 0.0, Size = 1.0, Fine = 1.0;
  int Across = 4, Levels = 2;
  MedialComplex C;
  std::vector<std::vector<int>> NodeColumn;
  std::vector<int> NodeMid;
  static constexpr double NaN = std::numeric_limits<double>::quiet_NaN();
};
} // namespace

int governorOfGenerator(const Generators& profile, int g)
{
  const Generator& gen = profile[g];
  const int edges = static_cast<int>(profile.boundary().edges().size());
  return gen.kind == GeneratorKind::Edge ? gen.edge : edges + 2 + gen.vertex;
}

MedialComplex computeMAT25D(const Generators& profile, const MedialGraph& profileMAT,
  const SweepMap& sweep, const MAT25DOptions& options)
{
  return Builder(profile, profileMAT, sweep, options).run();
}

} // namespace exactmat
