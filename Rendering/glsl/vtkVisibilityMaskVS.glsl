// ApertureLighting: visibility masks evaluated per vertex, for vtkApertureLightingInterface's
// vertex shader. Needs vtkSphericalCapGLSL, vtkApertureLightCapGLSL, vtkVisibilityMaskGLSL (the
// twin of vtkVisibilityMask, which does the work) and APERTURE_LIGHT_COUNT. Bits do not
// interpolate: the vertex evaluates its mask and the fragments interpolate the results.

uniform vec3 apertureLightCap[APERTURE_LIGHT_COUNT];
uniform float apertureLightWorldRadius[APERTURE_LIGHT_COUNT];
uniform mat3 apertureViewToModel;
uniform int apertureSkyCosine;

// The lights' coverage of the vertex's open cells, summed (solid angle, integral of n . w), and
// the open cells' own sums (vtkVisibilityMask::OpenSums()).
vec2 apertureMaskCoverage;
vec2 apertureMaskOpen;

// Fills visibilityMaskWords and apertureMaskOpen from the vertex's packed mask: its bytes three
// to a float (exact integers), four floats to an attribute; the last float holds the open cells'
// count plus 512 times their cosine integral over pi in 15 bits.
void apertureMaskUnpack(vec4 codes[APERTURE_MASK_ATTRIBUTES])
{
  uint sums = uint(codes[APERTURE_MASK_ATTRIBUTES - 1].w);
  apertureMaskOpen = vec2(float(sums & 511u) * 2.0 * sphericalCapPi / float(visibilityMaskCells),
    float(sums >> 9u) * sphericalCapPi / 32767.0);
  for (int w = 0; w < (visibilityMaskCells + 31) / 32; ++w)
  {
    uint word = 0u;
    for (int j = 0; j < 4; ++j)
    {
      int b = 4 * w + j;
      uint three = uint(codes[b / 12][(b / 3) % 4]);
      word |= ((three >> uint(8 * (b % 3))) & 255u) << uint(8 * j);
    }
    visibilityMaskWords[w] = word;
  }
}

// A light's transfer through the mask around the model normal nModel and the solid angle of it
// in open cells; its coverage adds to apertureMaskCoverage.
vec2 apertureMaskLight(vec3 nModel, sphericalCapCap light)
{
  vec2 coverage;
  float transfer = visibilityMaskLightTransfer(
    nModel, apertureViewToModel * light.axis, light.radius, coverage);
  apertureMaskCoverage += coverage;
  return vec2(transfer, coverage.x);
}
