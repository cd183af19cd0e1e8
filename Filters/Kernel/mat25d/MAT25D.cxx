#include "MAT25D.h"

#include "common/Format.h"
#include "common/InputError.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace exactmat
{

namespace
{
std::string point2(const Vec2& p)
{
  return "(" + format(p.x()) + ", " + format(p.y()) + ")";
}

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
  int top = -1;
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
    checkSpan();
    chooseResolution();
    NodeColumn.resize(M.nodes.size());
    for (size_t n = 0; n < M.nodes.size(); ++n)
      buildNode(static_cast<int>(n));
    const size_t total = M.segments.size();
    for (size_t k = 0; k < total; ++k)
    {
      buildSegment(static_cast<int>(k));
      if (O.progress)
        O.progress(static_cast<double>(k + 1) / static_cast<double>(total));
    }
    return std::move(C);
  }

private:
  // The method's precondition (§5.5.1): the profile faces a maximal-disk diameter apart.
  void checkSpan() const
  {
    if (W.closed())
      return;
    const RequiredSpan need = requiredHalfSpan(M, W);
    if (2.0 * need.capSpan <= S * (1.0 + 1e-12))
      return;
    if (W.kind() == SweepKind::Extrusion)
    {
      fail("2.5D MAT: the extrusion of length ", format(S), " is shorter than 2·Rmax = ",
        format(2.0 * need.radius), " (Rmax = ", format(need.radius), " at profile point ",
        point2(need.at), "); the end faces must be at least one maximal-disk diameter apart "
        "(thesis §5.5.1)");
    }
    fail("2.5D MAT: the revolution by ", format(S * 180.0 / Pi), "° is smaller than "
      "2·asin(r/x) = ", format(2.0 * need.capSpan * 180.0 / Pi), "° for the maximal disk of "
      "radius r = ", format(need.radius), " at profile point ", point2(need.at), ", x = ",
      format(W.axisDistance(need.at)), " from the axis; the end faces must be at least one "
      "maximal-disk diameter apart (thesis §5.5.1)");
  }

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
    const double h = std::max(1e-6, O.sheetResolution) * Size;
    Across = std::clamp(static_cast<int>(std::ceil(sweepLength / h)), 4, 4096);
    if (W.closed())
      Across = std::max(Across, 24);
    double rmax = 0.0;
    for (const MedialNode& n : M.nodes)
      rmax = std::max(rmax, n.sample.radius);
    for (const MedialSegment& s : M.segments)
      for (const MedialSample& x : s.samples)
        rmax = std::max(rmax, x.radius);
    Levels = std::clamp(static_cast<int>(std::ceil(rmax / h)), 2, 1024);
  }

  int addPoint(const Vec3& x, double r, MedialPoint3DType type, int contacts)
  {
    C.points.push_back({ x, r, type, contacts });
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
    switch (node.type)
    {
      case MedialPointType::Branch:
        NodeColumn[n] = column(x, r, T::Junction, feet > 0 ? feet + 1 : 0, T::Seam, feet);
        addCurve(MedialElementType::Seam, NodeColumn[n], govs, n);
        if (!W.closed())
        {
          addJunction(NodeColumn[n].front(), govs, E, n);
          if (NodeColumn[n].back() != NodeColumn[n].front())
            addJunction(NodeColumn[n].back(), govs, E + 1, n);
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

  void addJunction(int id, std::vector<int> govs, int face, int n)
  {
    govs.insert(govs.begin(), face);
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

  void buildSegment(int k)
  {
    const MedialSegment& seg = M.segments[k];
    // Samples that repeat their predecessor or the end node (a tracer's first step can
    // land on its node) would be a second, mislabelled copy of that point.
    std::vector<MedialSample> samples{ seg.samples.front() };
    const double same = 1e-12 * Size;
    for (size_t i = 1; i + 1 < seg.samples.size(); ++i)
    {
      const Vec2& x = seg.samples[i].x;
      if ((x - samples.back().x).norm() > same && (x - seg.samples.back().x).norm() > same)
        samples.push_back(seg.samples[i]);
    }
    samples.push_back(seg.samples.back());
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
      if (travelled >= spacing && ahead >= 0.5 * spacing)
      {
        sheetColumn[i] = true;
        travelled = 0.0;
      }
    }
    std::vector<std::vector<int>> columns(n);
    columns.front() = NodeColumn[seg.startNode];
    columns.back() = NodeColumn[seg.endNode];
    for (size_t i = 1; i + 1 < n; ++i)
    {
      const MedialSample& s = samples[i];
      if (sheetColumn[i])
        columns[i] = column(s.x, s.radius, MedialPoint3DType::Seam, 3, MedialPoint3DType::Sheet, 2);
      else if (!W.closed())
        columns[i] = seamPoints(s.x, s.radius);
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

    // The swept sheet between the seams.
    MedialElement sheet;
    sheet.type = MedialElementType::SweptSheet;
    sheet.governors = govAB;
    sheet.profileSegment = k;
    const int rows = static_cast<int>(columns.front().size());
    for (size_t i = 0, next = 1; next < n; i = next++)
    {
      while (!sheetColumn[next])
        ++next;
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

    // The seams on both profile faces, and the profile sheets below them.
    for (int face = 0; face < 2; ++face)
    {
      std::vector<int> seam;
      for (size_t i = 0; i < n; ++i)
        seam.push_back(face == 0 ? columns[i].front() : columns[i].back());
      std::vector<int> govs = govAB;
      govs.insert(govs.begin(), E + face);
      addPolyline(MedialElementType::Seam, seam, govs, k);
      for (int side = 0; side < 2; ++side)
      {
        std::vector<StripColumn> strip;
        for (size_t i = 0; i < n; ++i)
        {
          const MedialSample& s = samples[i];
          if (sheetColumn[i])
            strip.push_back({ s.foot[side].point, s.x, s.radius, seam[i] });
        }
        std::vector<int> sg = side == 0 ? govA : govB;
        sg.insert(sg.begin(), E + face);
        profileSheet(face, strip, sg, k);
      }
    }
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
      if (c.r <= 0.0 && (c.x - c.foot).norm() <= 1e-15 * Size)
      {
        ids.assign(Levels + 1, c.top); // a convex vertex: the column is one point
        previousFootId = -1;
        continue;
      }
      // Footpoints repeat along a reflex corner: one boundary point.
      const bool sameFoot = previousFootId >= 0 && (c.foot - previousFoot).norm() <= 1e-15 * Size;
      const int footId = sameFoot ? previousFootId
                                  : addPoint(W.place(c.foot, face == 0 ? 0.0 : S), 0.0,
                                      MedialPoint3DType::ConvexEdge, 0);
      previousFootId = footId;
      previousFoot = c.foot;
      ids.push_back(footId);
      for (int q = 1; q < Levels; ++q)
      {
        const double t = static_cast<double>(q) / Levels;
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

  // A circular profile: its profile sheets are cones from the circle to the centre.
  void circleProfileSheets(int n)
  {
    const MedialNode& node = M.nodes[n];
    const double h = std::max(1e-6, O.sheetResolution) * Size;
    for (int face = 0; face < 2; ++face)
    {
      const int apex = face == 0 ? NodeColumn[n].front() : NodeColumn[n].back();
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
          strip.push_back({ G.evaluate(f.g, static_cast<double>(i) / count).p, node.sample.x,
            node.sample.radius, apex });
        profileSheet(face, strip, { E + face, governorOfGenerator(G, f.g) }, n);
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
  double S = 0.0, Size = 1.0;
  int Across = 4, Levels = 2;
  MedialComplex C;
  std::vector<std::vector<int>> NodeColumn;
  static constexpr double NaN = std::numeric_limits<double>::quiet_NaN();
};
} // namespace

int governorOfGenerator(const Generators& profile, int g)
{
  const Generator& gen = profile[g];
  const int edges = static_cast<int>(profile.boundary().edges().size());
  return gen.kind == GeneratorKind::Edge ? gen.edge : edges + 2 + gen.vertex;
}

RequiredSpan requiredHalfSpan(const MedialGraph& profileMAT, const SweepMap& sweep)
{
  RequiredSpan need;
  auto consider = [&](const MedialSample& s) {
    const double span = sweep.capSpan(s.x, s.radius);
    if (span > need.capSpan)
      need = { span, s.radius, s.x };
  };
  for (const MedialNode& n : profileMAT.nodes)
    consider(n.sample);
  for (const MedialSegment& seg : profileMAT.segments)
    for (const MedialSample& s : seg.samples)
      consider(s);
  return need;
}

MedialComplex computeMAT25D(const Generators& profile, const MedialGraph& profileMAT,
  const SweepMap& sweep, const MAT25DOptions& options)
{
  return Builder(profile, profileMAT, sweep, options).run();
}

} // namespace exactmat
