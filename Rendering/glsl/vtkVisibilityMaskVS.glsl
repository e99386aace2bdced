// ApertureLighting: visibility masks evaluated per vertex, for vtkApertureLightingInterface's
// vertex shader (vtkApertureVertexLightingVS first). Needs vtkVisibilityMaskGLSL (the twin of
// vtkVisibilityMask, which does the work) and APERTURE_PACKED_ATTRIBUTES.

// Fills visibilityMaskWords from the vertex's packed mask: its bytes three to a float (exact
// integers), four floats to an attribute.
void apertureVertexPrepare(vec4 codes[APERTURE_PACKED_ATTRIBUTES])
{
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
// in open cells.
vec2 apertureVertexLight(vec3 nModel, sphericalCapCap light)
{
  vec2 coverage;
  float transfer = visibilityMaskLightTransfer(
    nModel, apertureViewToModel * light.axis, light.radius, coverage);
  apertureVertexCoverage += coverage;
  return vec2(transfer, coverage.x);
}
