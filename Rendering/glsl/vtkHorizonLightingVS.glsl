// ApertureLighting: horizons evaluated per vertex, for vtkApertureLightingInterface's vertex
// shader (vtkApertureVertexLightingVS first) where the data have point normals. Needs
// vtkHorizonLightingCodeGLSL, vtkHorizonLightingGLSL (the twin of vtkHorizonLighting, which does
// the work), HORIZON_LIGHTING_SECTORS and APERTURE_PACKED_ATTRIBUTES.

// Decodes the vertex's packed horizons into horizonLightingHorizons: 8-bit codes three to a
// float (exact integers), four floats to an attribute.
void apertureVertexPrepare(vec4 codes[APERTURE_PACKED_ATTRIBUTES])
{
  for (int k = 0; k < HORIZON_LIGHTING_SECTORS; ++k)
  {
    uint three = uint(codes[k / 12][(k / 3) % 4]);
    uint code = (three >> uint(8 * (k % 3))) & 255u;
    horizonLightingHorizons[k] = horizonLightingDecode(float(code) / 255.0);
  }
}

// A light's transfer above the horizons around the model normal nModel and the solid angle of
// it the point sees.
vec2 apertureVertexLight(vec3 nModel, sphericalCapCap light)
{
  vec2 sums;
  float transfer =
    horizonLightingLightTransfer(nModel, apertureViewToModel * light.axis, light.radius, sums);
  apertureVertexCoverage += sums;
  return vec2(transfer, sums.x);
}
