// Every catalogue shape builds a valid B-rep; parameters are checked.
#include "common/InputError.h"
#include "shapes/Catalogue.h"

#include <gtest/gtest.h>

using namespace exactmat;

TEST(Catalogue, EveryShapeBuilds)
{
  for (const std::string& name : catalogueNames())
  {
    const Shape s = makeShape(name);
    if (s.dimension == 2)
    {
      EXPECT_FALSE(s.curves.empty()) << name;
      EXPECT_NO_THROW(Boundary2D::build(curvePieces(s.curves))) << name;
    }
    else
    {
      EXPECT_FALSE(s.surfaces.empty()) << name;
      EXPECT_NO_THROW(Boundary3D::build(patchPieces(s.surfaces))) << name;
    }
  }
}

TEST(Catalogue, BadParametersAndNamesAreRejected)
{
  ShapeParameters p;
  p.width = -1;
  EXPECT_THROW(makeShape("rectangle", p), InputError);
  p = ShapeParameters();
  p.innerRadius = 2.0;
  EXPECT_THROW(makeShape("annulus", p), InputError);
  try
  {
    makeShape("dodecahedron");
    FAIL();
  }
  catch (const InputError& e)
  {
    EXPECT_NE(std::string(e.what()).find("unknown shape 'dodecahedron' (known: rectangle"), std::string::npos);
  }
}
