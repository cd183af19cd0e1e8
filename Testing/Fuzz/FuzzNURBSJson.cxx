// libFuzzer target: bytes as an ExactMAT JSON file, through the reader, the B-rep and the
// 2D MAT with its verification. Bad input must end in an InputError; a crash, a sanitizer
// report, any other exception or a hang is a finding.
#include "NURBSJson.h"

#include "brep/NormalisePieces.h"
#include "common/InputError.h"
#include "mat2d/Tracer.h"
#include "mat2d/Verification.h"
#include "shapes/Catalogue.h"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  using namespace exactmat;
  try
  {
    const Shape shape = parseNURBSJson(std::string(reinterpret_cast<const char*>(data), size), "fuzz.json");
    if (shape.dimension != 2 || shape.curves.size() > 64)
      return 0;
    const Boundary2D boundary = buildNormalised(curvePieces(shape.curves));
    if (boundary.edges().size() > 256)
      return 0;
    const Generators generators(boundary);
    MAT2DOptions options;
    // A runaway is an InputError, fast: 2,000 samples (adaptive segments take a few
    // hundred) keep the worst found — a weight of 1e18 beside 1, a segment that creeps and
    // took 17 s at 20,000 under the fuzzer's sanitizers — to a couple of seconds.
    options.maxSamplesPerSegment = 2000;
    options.maxSegments = 2000;
    const MedialGraph graph = computeMAT2D(generators, options);
    (void)verifyMAT2D(generators, graph);
  }
  catch (const InputError&)
  {
  }
  return 0;
}
