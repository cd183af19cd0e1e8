#include "NURBSJson.h"

#include "common/InputError.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace exactmat
{

namespace
{
using json = nlohmann::json;

std::vector<double> numbers(const json& j, const std::string& where)
{
  if (!j.is_array())
  {
    fail(where, " must be an array of numbers");
  }
  std::vector<double> v;
  for (size_t i = 0; i < j.size(); ++i)
  {
    if (!j[i].is_number())
    {
      fail(where, "[", i, "] is not a number");
    }
    v.push_back(j[i].get<double>());
  }
  return v;
}

Vec3List points(const json& j, const std::string& where)
{
  if (!j.is_array())
  {
    fail(where, " must be an array of [x, y] or [x, y, z] points");
  }
  Vec3List v;
  for (size_t i = 0; i < j.size(); ++i)
  {
    const std::vector<double> c = numbers(j[i], where + "[" + std::to_string(i) + "]");
    if (c.size() != 2 && c.size() != 3)
    {
      fail(where, "[", i, "] has ", c.size(), " coordinates (expected 2 or 3)");
    }
    v.emplace_back(c[0], c[1], c.size() == 3 ? c[2] : 0.0);
  }
  return v;
}

const json& field(const json& entry, const char* name, const std::string& where)
{
  if (!entry.contains(name))
  {
    fail(where, ": missing \"", name, "\"");
  }
  return entry.at(name);
}

// An integer in [lo, hi]: a degree of 4294967297 must not wrap to 1, nor 2.5 become 2.
int integer(const json& j, const std::string& where, long long lo, long long hi)
{
  const bool integral = j.is_number_integer() ||
    (j.is_number_float() && j.get<double>() == std::floor(j.get<double>()));
  const double v = j.is_number() ? j.get<double>() : 0.0;
  if (!integral || !(v >= static_cast<double>(lo) && v <= static_cast<double>(hi)))
  {
    fail(where, " must be an integer from ", lo, " to ", hi, " (got ", j.dump(), ")");
  }
  return static_cast<int>(v);
}

// Highest degree and largest control net a file may ask for (a typo such as 1e9 points
// per direction must be an error, not an allocation of gigabytes).
constexpr long long MaximumDegree = 32;
constexpr long long MaximumNetSize = 1000000;

// A rational curve or surface does not see a common factor of its weights: scale them so
// the largest is 1, which keeps w·x finite for weights like 1e300.
void normaliseWeights(std::vector<double>& w)
{
  double largest = 0.0;
  for (double x : w)
    largest = std::isfinite(x) ? std::max(largest, x) : largest;
  if (largest > 0.0 && largest != 1.0)
    for (double& x : w)
      x /= largest;
}
} // namespace

Shape parseNURBSJson(const std::string& text, const std::string& source)
{
  json doc;
  try
  {
    doc = json::parse(text);
  }
  catch (const json::exception& e)
  {
    // parse_error, and out_of_range for a number a double cannot hold (1e999)
    fail(source, ": not valid JSON (", e.what(), ")");
  }
  if (!doc.is_object())
  {
    fail(source, ": the top level must be an object");
  }
  if (doc.contains("format") && doc["format"] != "exactmat-nurbs")
  {
    fail(source, ": \"format\" is ", doc["format"].dump(), ", expected \"exactmat-nurbs\"");
  }
  if (doc.contains("version") && doc["version"] != 1)
  {
    fail(source, ": unsupported version ", doc["version"].dump(), " (this reader knows 1)");
  }
  Shape shape;
  shape.name = source;
  if (doc.contains("curves"))
  {
    const json& curves = doc["curves"];
    if (!curves.is_array())
    {
      fail(source, ": \"curves\" must be an array");
    }
    for (size_t i = 0; i < curves.size(); ++i)
    {
      const std::string where = source + ": curves[" + std::to_string(i) + "]";
      const json& c = curves[i];
      const int degree = integer(field(c, "degree", where), where + ".degree", 1, MaximumDegree);
      const KnotVector knots = numbers(field(c, "knots", where), where + ".knots");
      const Vec3List pts = points(field(c, "points", where), where + ".points");
      std::vector<double> w;
      if (c.contains("weights"))
      {
        w = numbers(c["weights"], where + ".weights");
        if (w.size() != pts.size())
        {
          fail(where, ": ", w.size(), " weights for ", pts.size(), " points");
        }
        normaliseWeights(w);
      }
      NurbsCurve curve(degree, knots, pts, w);
      curve.validate(where);
      shape.curves.push_back(std::move(curve));
    }
  }
  if (doc.contains("surfaces"))
  {
    const json& surfaces = doc["surfaces"];
    if (!surfaces.is_array())
    {
      fail(source, ": \"surfaces\" must be an array");
    }
    for (size_t i = 0; i < surfaces.size(); ++i)
    {
      const std::string where = source + ": surfaces[" + std::to_string(i) + "]";
      const json& s = surfaces[i];
      const json& degreeField = field(s, "degree", where);
      const json& sizeField = field(s, "size", where);
      const json& knots = field(s, "knots", where);
      if (!degreeField.is_array() || degreeField.size() != 2 || !sizeField.is_array() ||
        sizeField.size() != 2 || !knots.is_array() || knots.size() != 2)
      {
        fail(where, ": \"degree\", \"size\" and \"knots\" must each have two entries (u, v)");
      }
      const int deg[2] = { integer(degreeField[0], where + ".degree[0]", 1, MaximumDegree),
        integer(degreeField[1], where + ".degree[1]", 1, MaximumDegree) };
      const int size[2] = { integer(sizeField[0], where + ".size[0]", 1, MaximumNetSize),
        integer(sizeField[1], where + ".size[1]", 1, MaximumNetSize) };
      const Vec3List pts = points(field(s, "points", where), where + ".points");
      std::vector<double> w;
      if (s.contains("weights"))
      {
        w = numbers(s["weights"], where + ".weights");
        normaliseWeights(w);
      }
      const int nu = size[0], nv = size[1];
      if (pts.size() != static_cast<size_t>(nu) * static_cast<size_t>(nv) ||
        (!w.empty() && w.size() != pts.size()))
      {
        fail(where, ": ", pts.size(), " points and ", w.size(), " weights for a ", nu, " x ", nv,
          " net");
      }
      NurbsSurface surface(deg[0], deg[1],
        numbers(knots[0], where + ".knots[0]"), numbers(knots[1], where + ".knots[1]"), nu, nv,
        pts, w);
      surface.validate(where);
      shape.surfaces.push_back(std::move(surface));
    }
  }
  if (shape.curves.empty() && shape.surfaces.empty())
  {
    fail(source, ": empty input (no \"curves\" and no \"surfaces\")");
  }
  if (!shape.curves.empty() && !shape.surfaces.empty())
  {
    fail(source, ": holds both curves and surfaces; a file describes a 2D domain or a solid");
  }
  shape.dimension = shape.curves.empty() ? 3 : 2;
  return shape;
}

std::string writeNURBSJson(const Shape& shape, const std::vector<int>& ids)
{
  // nlohmann prints doubles with enough digits to read back the same value.
  json doc;
  doc["format"] = "exactmat-nurbs";
  doc["version"] = 1;
  auto pointList = [](const Vec4List& h) {
    json pts = json::array(), w = json::array();
    for (const Vec4& p : h)
    {
      const Vec3 e = euclidean(p);
      pts.push_back({ e.x(), e.y(), e.z() });
      w.push_back(p.w());
    }
    return std::make_pair(pts, w);
  };
  size_t k = 0;
  if (!shape.curves.empty())
  {
    doc["curves"] = json::array();
    for (const NurbsCurve& c : shape.curves)
    {
      json e;
      e["id"] = k < ids.size() ? ids[k] : static_cast<int>(k);
      e["degree"] = c.degree();
      e["knots"] = c.knots();
      auto [pts, w] = pointList(c.homogeneousPoints());
      e["points"] = pts;
      e["weights"] = w;
      doc["curves"].push_back(e);
      ++k;
    }
  }
  if (!shape.surfaces.empty())
  {
    doc["surfaces"] = json::array();
    for (const NurbsSurface& s : shape.surfaces)
    {
      json e;
      e["id"] = k < ids.size() ? ids[k] : static_cast<int>(k);
      e["degree"] = { s.degreeU(), s.degreeV() };
      e["knots"] = { s.knotsU(), s.knotsV() };
      e["size"] = { s.countU(), s.countV() };
      auto [pts, w] = pointList(s.homogeneousNet());
      e["points"] = pts;
      e["weights"] = w;
      doc["surfaces"].push_back(e);
      ++k;
    }
  }
  return doc.dump(1) + "\n";
}

} // namespace exactmat
