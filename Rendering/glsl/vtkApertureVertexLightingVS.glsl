// ApertureLighting: lights evaluated per vertex, for vtkApertureLightingInterface's vertex
// shader where the data beyond one cap cannot interpolate (visibility masks) or need not
// (horizons with point normals). Needs vtkSphericalCapGLSL, vtkApertureLightCapGLSL and
// APERTURE_LIGHT_COUNT, then a mode's source that defines apertureVertexPrepare() (reads the
// vertex's packed attributes) and apertureVertexLight() (a light's transfer and the solid angle
// of it the point sees, adding its coverage to apertureVertexCoverage).

uniform vec3 apertureLightCap[APERTURE_LIGHT_COUNT];
uniform float apertureLightWorldRadius[APERTURE_LIGHT_COUNT];
uniform mat3 apertureViewToModel;
uniform int apertureSkyCosine;

// The lights' coverage of what the vertex sees, summed (solid angle, integral of n . w), and
// what the vertex sees of the sky, in the same sums (the OpenSums() of vtkVisibilityMask or
// vtkHorizonLighting, from the CPU).
vec2 apertureVertexCoverage;
vec2 apertureVertexOpen;

// The open sums from the last float of the packed attributes: the solid angle over 4 pi plus
// 4096 times the cosine integral over pi, each in 12 bits.
void apertureVertexUnpackSums(float code)
{
  uint sums = uint(code);
  apertureVertexOpen = vec2(float(sums & 4095u) * 4.0 * sphericalCapPi / 4095.0,
    float(sums >> 12u) * sphericalCapPi / 4095.0);
}

// The uniform sky through what the vertex sees, less what the lights cover (the SkyTransfer()
// of vtkVisibilityMask and vtkHorizonLighting).
float apertureVertexSky()
{
  return apertureSkyCosine != 0
    ? max(0.0, apertureVertexOpen.y - apertureVertexCoverage.y) / sphericalCapPi
    : max(0.0, apertureVertexOpen.x - apertureVertexCoverage.x) / (2.0 * sphericalCapPi);
}

// The environment sky through what the vertex sees, from the CPU without the lights
// (EnvironmentSkyTransfer() of vtkVisibilityMask or vtkHorizonLighting), less the share of the
// open sky the lights cover.
vec3 apertureVertexEnvironmentSky(vec3 sky)
{
  float all = apertureSkyCosine != 0 ? apertureVertexOpen.y : apertureVertexOpen.x;
  float lost = apertureSkyCosine != 0 ? apertureVertexCoverage.y : apertureVertexCoverage.x;
  return all > 0.0 ? sky * max(0.0, 1.0 - lost / all) : vec3(0.0);
}
