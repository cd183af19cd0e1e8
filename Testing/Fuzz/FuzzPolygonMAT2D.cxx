// libFuzzer target: bytes as a small polygon (up to 24 vertices, 16-bit coordinates, so
// near-coincident, collinear and self-touching vertices are common), moved and scaled by
// the first bytes, through the 2D MAT and its verification. Invalid polygons must be
// InputErrors; anything else that escapes, crashes or hangs is a finding.
#include "brep/NormalisePieces.h"
#include "common/InputError.h"
#include "mat2d/Tracer.h"
#include "mat2d/Verification.h"
#include "shapes/Catalogue.h"
#include "shapes/Primitives.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  using namespace exactmat;
  if (size < 2 + 3 * 4)
    return 0;
  // Byte 0: the power of ten of the scale; byte 1: of the offset (as a multiple of it).
  const double scale = std::pow(10.0, static_cast<int>(data[0] % 25) - 12);
  const double offset = scale * std::pow(10.0, static_cast<int>(data[1] % 9) - 1);
  data += 2;
  size -= 2;
  Vec3List corners;
  for (size_t i = 0; i + 4 <= size && corners.size() < 24; i += 4)
  {
    int16_t x, y;
    std::memcpy(&x, data + i, 2);
    std::memcpy(&y, data + i + 2, 2);
    corners.push_back(Vec3(offset + scale * x / 32768.0, offset + scale * y / 32768.0, 0.0));
  }
  try
  {
    const Boundary2D boundary = buildNormalised(curvePieces(makePolygon(corners)));
    const Generators generators(boundary);
    MAT2DOptions options;
    options.maxSamplesPerSegment = 20000;
    options.maxSegments = 2000;
    const MedialGraph graph = computeMAT2D(generators, options);
    (void)verifyMAT2D(generators, graph);
  }
  catch (const InputError&)
  {
  }
  return 0;
}
