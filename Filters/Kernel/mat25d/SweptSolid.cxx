#include "SweptSolid.h"

#include "mat2d/Bisector.h"

#include <algorithm>
#include <cmath>

namespace exactmat
{

namespace
{
// A point of the profile boundary: generator and parameter.
struct Foot
{
  int g = -1;
  double s = 0.0;
  Vec2 point = Vec2::Zero();
};

// The profile MAT with samples at most `longest` apart along its segments between two
// straight edges. The tracer steps along such a segment as far as one sweep of its disks
// allows (the segment is straight and its radius linear: a long chord is exact), but a
// strip that long is a tile much longer than wide, and the sheets parameterised on it lose
// accuracy along their borders: the tiles keep the tracer's usual step (points solved on
// the exact bisector).
MedialGraph withChordsAtMost(const Generators& G, const MedialGraph& mat, double longest)
{
  MedialGraph out = mat;
  for (MedialSegment& seg : out.segments)
  {
    std::vector<MedialSample> dense;
    for (size_t i = 0; i < seg.samples.size(); ++i)
    {
      const MedialSample& q = seg.samples[i];
      if (i > 0)
      {
        const MedialSample& p = seg.samples[i - 1];
        const int ga = p.foot[0].g, gb = p.foot[1].g;
        const double chord = (q.x - p.x).norm();
        if (chord > longest && ga >= 0 && gb >= 0 && ga == q.foot[0].g && gb == q.foot[1].g &&
          G[ga].kind == GeneratorKind::Edge && G[gb].kind == GeneratorKind::Edge && G.straight(ga) && G.straight(gb))
        {
          const Bisector B(G, ga, gb);
          const int pieces = static_cast<int>(std::min(1e4, std::ceil(chord / longest)));
          for (int j = 1; j < pieces; ++j)
          {
            const double f = static_cast<double>(j) / pieces;
            BisectorState y{ p.foot[0].s + f * (q.foot[0].s - p.foot[0].s), p.foot[1].s + f * (q.foot[1].s - p.foot[1].s),
              p.radius + f * (q.radius - p.radius) };
            GeneratorPoint a, b;
            if (!B.correct(y, 0, 1e-13 * G.size2D(), &a, &b))
              continue;
            MedialSample m;
            m.x = a.p + y.r * a.n;
            m.radius = y.r;
            m.foot[0] = { ga, y.sa, a.p, a.n, false };
            m.foot[1] = { gb, y.sb, b.p, b.n, false };
            dense.push_back(m);
          }
        }
      }
      dense.push_back(q);
    }
    seg.samples = std::move(dense);
  }
  return out;
}

class CapTiler
{
public:
  CapTiler(const Generators& g, const SweepMap& w)
    : G(g)
    , W(w)
    , Splits(g.boundary().edges().size())
  {
  }

  // Walks the boundary from a to b (forward along the loop when `forward`), returning
  // the pieces in between in the profile frame, each from a's side to b's side: a piece
  // of an edge, or a corner (a point) for reflex-corner generators.
  std::vector<BezierCurve> boundaryBetween(const Foot& a, const Foot& b, bool forward)
  {
    std::vector<BezierCurve> pieces;
    int g = a.g;
    double s = a.s;
    for (int guard = 0; guard <= G.size() + 1; ++guard)
    {
      const bool last = g == b.g && (forward ? b.s >= s - 1e-14 : b.s <= s + 1e-14);
      const double end = last ? b.s : (forward ? 1.0 : 0.0);
      appendPiece(g, s, end, pieces);
      if (last)
        return pieces;
      g = forward ? G[g].next : G[g].prev;
      s = forward ? 0.0 : 1.0;
    }
    return pieces; // not reached on a valid MAT: footpoints move monotonically
  }

  void appendPiece(int g, double s0, double s1, std::vector<BezierCurve>& pieces)
  {
    const Generator& gen = G[g];
    if (gen.kind == GeneratorKind::ReflexCorner)
    {
      const Vec3 c = G.boundary().vertices()[gen.vertex].point;
      pieces.push_back(BezierCurve({ Vec4(c.x(), c.y(), 0.0, 1.0), Vec4(c.x(), c.y(), 0.0, 1.0) }));
      return;
    }
    if (std::abs(s1 - s0) <= 1e-14)
      return;
    const BezierCurve& curve = G.boundary().edges()[gen.edge].curve;
    const double lo = std::min(s0, s1), hi = std::max(s0, s1);
    for (double t : { lo, hi })
      if (t > 1e-14 && t < 1.0 - 1e-14)
        Splits[gen.edge].push_back(t);
    const BezierCurve piece = curve.segment(lo, hi).inStandardForm();
    pieces.push_back(s1 >= s0 ? piece : piece.reversed());
  }

  // The strip between boundary pieces (from F_i to F_{i+1}) and the chord x_i → x_{i+1},
  // the chord split in proportion to the pieces' chord lengths.
  void strip(std::vector<BezierCurve> pieces, const Vec2& x0, const Vec2& x1)
  {
    // A reflex corner passed on the way to an edge (the footpoint steps from one edge's end
    // over the corner onto the next edge: a corner of no sweep between two samples) would
    // get a point of the chord: a patch of no area whose ruling sides coincide, which
    // makes the ruling at the corner an edge of three faces. The edge pieces take the chord.
    auto isPoint = [](const BezierCurve& c) {
      for (const Vec4& h : c.homogeneousPoints())
        if (euclidean(h) != c.startPoint())
          return false;
      return true;
    };
    if (std::any_of(pieces.begin(), pieces.end(), [&](const BezierCurve& c) { return !isPoint(c); }))
      pieces.erase(std::remove_if(pieces.begin(), pieces.end(), isPoint), pieces.end());
    double total = 0.0;
    std::vector<double> lengths;
    for (const BezierCurve& c : pieces)
    {
      lengths.push_back((c.endPoint() - c.startPoint()).norm() + 1e-300);
      total += lengths.back();
    }
    double done = 0.0;
    for (size_t k = 0; k < pieces.size(); ++k)
    {
      const double f0 = done / total, f1 = (done + lengths[k]) / total;
      done += lengths[k];
      const Vec2 a = x0 + f0 * (x1 - x0), b = x0 + f1 * (x1 - x0);
      Strips.push_back({ pieces[k], a, b });
    }
  }

  // Footpoint parameters that agree to 1e-7 are one (the same branch point's footpoint
  // reached by two segments differs in the last digits): snapped to their cluster's first.
  void collectSnaps(const MedialGraph& mat)
  {
    Snaps.assign(G.boundary().edges().size(), {});
    for (const MedialSegment& seg : mat.segments)
      for (const MedialSample& x : seg.samples)
        for (const BoundaryLocation& f : x.foot)
          if (f.g >= 0 && G[f.g].kind == GeneratorKind::Edge)
            Snaps[G[f.g].edge].push_back(f.s);
    for (std::vector<double>& v : Snaps)
    {
      v.push_back(0.0);
      v.push_back(1.0);
      std::sort(v.begin(), v.end());
      std::vector<double> clusters;
      for (double t : v)
        if (clusters.empty() || t - clusters.back() > SnapTolerance)
          clusters.push_back(t);
      if (clusters.size() > 1 && 1.0 - clusters.back() <= SnapTolerance)
        clusters.back() = 1.0;
      v = clusters;
    }
  }

  double snap(int g, double s) const
  {
    if (G[g].kind != GeneratorKind::Edge)
      return s;
    const std::vector<double>& v = Snaps[G[g].edge];
    auto it = std::lower_bound(v.begin(), v.end(), s - SnapTolerance);
    return (it != v.end() && std::abs(*it - s) <= SnapTolerance) ? *it : s;
  }

  // The strips of every segment, both sides.
  void tile(const MedialGraph& mat)
  {
    collectSnaps(mat);
    for (const MedialSegment& seg : mat.segments)
    {
      for (int side = 0; side < 2; ++side)
      {
        for (size_t i = 0; i + 1 < seg.samples.size(); ++i)
        {
          const MedialSample& p = seg.samples[i];
          const MedialSample& q = seg.samples[i + 1];
          if ((q.x - p.x).norm() <= 1e-14 * G.size2D() && (q.foot[side].point - p.foot[side].point).norm() <= 1e-14 * G.size2D())
            continue;
          const Foot a{ p.foot[side].g, snap(p.foot[side].g, p.foot[side].s), p.foot[side].point };
          const Foot b{ q.foot[side].g, snap(q.foot[side].g, q.foot[side].s), q.foot[side].point };
          strip(boundaryBetween(a, b, side == 0), p.x, q.x);
        }
      }
    }
    for (const MedialNode& n : mat.nodes)
    {
      if (n.type != MedialPointType::CircleCentre)
        continue;
      for (const BoundaryLocation& f : n.footpoints)
        strip(boundaryBetween({ f.g, 0.0, {} }, { f.g, 1.0, {} }, true), n.sample.x, n.sample.x);
    }
  }

  // The planar patch ruled between a strip's boundary piece and its chord, at τ.
  BezierPatch patch(const BezierCurve& piece, const Vec2& a, const Vec2& b, double tau) const
  {
    const int p = piece.degree();
    Vec4List net;
    for (int k = 0; k <= p; ++k)
    {
      net.push_back(W.placeHomogeneous(piece.homogeneousPoints()[k], tau));
      const Vec2 c = a + (static_cast<double>(k) / p) * (b - a);
      net.push_back(W.placeHomogeneous(Vec4(c.x(), c.y(), 0.0, 1.0), tau));
    }
    return BezierPatch(p, 1, net);
  }

  const Generators& G;
  const SweepMap& W;
  std::vector<std::vector<double>> Splits; ///< per edge: where strips cut it
  std::vector<std::vector<double>> Snaps;  ///< per edge: footpoint parameter clusters
  static constexpr double SnapTolerance = 1e-7;
  struct Strip
  {
    BezierCurve piece;
    Vec2 a, b;
  };
  std::vector<Strip> Strips;
};
} // namespace

std::vector<PatchPiece> sweptSolidFaces(
  const Generators& profile, const MedialGraph& profileMAT, const SweepMap& sweep)
{
  CapTiler tiler(profile, sweep);
  if (!sweep.closed())
    tiler.tile(withChordsAtMost(profile, profileMAT, 0.05 * profile.size2D()));
  for (std::vector<double>& cuts : tiler.Splits)
  {
    std::sort(cuts.begin(), cuts.end());
    std::vector<double> unique;
    for (double t : cuts)
      if (unique.empty() || t - unique.back() > 1e-12)
        unique.push_back(t);
    cuts = unique;
  }
  std::vector<PatchPiece> faces = sweep.sideFaces(tiler.Splits);
  int maxEntity = -1;
  for (const Edge2D& e : profile.boundary().edges())
    maxEntity = std::max(maxEntity, e.entity);
  for (int face = 0; face < 2 && !sweep.closed(); ++face)
  {
    const double tau = face == 0 ? 0.0 : sweep.span();
    for (const auto& s : tiler.Strips)
      faces.push_back({ tiler.patch(s.piece, s.a, s.b, tau), std::nullopt, maxEntity + 1 + face });
  }
  return faces;
}

} // namespace exactmat
