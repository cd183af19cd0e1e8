#pragma once
/// @file CentreCurve.h
/// @brief Curves of centres of balls that touch a face along a whole circle, or an arc of
/// one: a cylinder's or cone's axis, a torus' core, a pipe's or a rolling-ball fillet's
/// spine — the canal surfaces CAD parts are made of (issue 10: "circles of contact").
///
/// Where a face is the envelope of a family of spheres, its characteristic circles are
/// lines of curvature along which the normals all meet at the sphere's centre: along the
/// circle's direction e1 the normal curvature is κ1 = 1/r and the focal point
/// F = P + N/κ1 does not move (by Rodrigues, dF/de1 = N·d(1/κ1)/de1: a ridge everywhere,
/// the ridge function of Rim.h vanishing identically). The ball centred at F with radius
/// 1/κ1 touches the whole circle; it is medial where it is empty (κ1 the larger curvature,
/// nothing else of the solid inside). Such a point is recognised by F standing still over
/// a tenth of a radian of the circle (a generic ridge's F moves by about 1e-3·r there), and
/// the curve is traced by moving the touch across the circles (along e2) with chord
/// control on the centres, onto smooth neighbours, until the ball stops being empty
/// (bisected: the ball touching the circle and another entity, a cone sheet's apex), its
/// touch reaches a sharp edge, the face stops being a canal surface, or the curve closes.

#include "mat3d/FaceCurveSearch.h"

#include <functional>
#include <string>
#include <vector>

namespace exactmat
{

struct CircleBall
{
  int face = -1;         ///< the face of the tracked touch
  Vec2 q = Vec2::Zero(); ///< its parameters
  Vec3 touch = Vec3::Zero(); ///< one point of the circle of contact
  Vec3 x = Vec3::Zero(); ///< the centre
  double r = 0.0;
};

struct CentreCurve
{
  std::vector<CircleBall> balls; ///< in order; a closed curve repeats its first ball at the end
  bool closed = false;
  /// Why each end (front, back) ended; empty when closed.
  std::string frontEnd, backEnd;
  /// Whether each end's ball stopped being empty there (it touches another entity: the
  /// end is a node of the MAT where sheets meet the curve), else the touch reached a
  /// sharp edge or the face stopped being a canal surface.
  bool frontBlocked = false, backBlocked = false;
};

struct CentreCurveSearch : FaceCurveSearch
{
  /// A face that enters the ball (centre, radius), or −1 when it is empty of the whole
  /// boundary; it touches a circle of a face, so the test is meant against a ball smaller
  /// by a relative 1e-6. Where a face enters, the end is put where its distance equals the
  /// radius.
  std::function<int(const Vec3&, double)> entering;
};

/// Whether the touch at q of a curved face lies on a circle of contact (see the file
/// comment); if so, that ball's centre and radius.
bool onCircleOfContact(const Generator3D& face, const Vec2& q, double size, Vec3& centre, double& radius);

/// Every centre curve of the solid's curved faces, from samples of each face whose ball is
/// empty, each traced both ways until it closes or ends. Throws InputError when a trace
/// runs away.
std::vector<CentreCurve> traceCentreCurves(const CentreCurveSearch& search);

/// The circle of contact through the touch at q of a face, for the ball centred at
/// `centre`: the line of curvature along κ1 there, `samples` points of it (its plane holds
/// the touch, the centre and κ1's direction).
Vec3List contactCircle(const Generator3D& face, const Vec2& q, const Vec3& centre, int samples);

} // namespace exactmat
