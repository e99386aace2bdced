#version 430 core
// vtkVisibilityMatrixPasses' DepthCompare depth pass, for a direction and its opposite at once: the
// nearest and the farthest surface in each texel (blending with GL_MIN and GL_MAX), each pushed
// away from its light by the offset glPolygonOffset(factor, units) gives a depth pass.
uniform float offsetFactor;
uniform float offsetUnits;
layout(location = 0) out float nearest;
layout(location = 1) out float farthest;
void main()
{
  // The polygon's largest depth slope and the resolution of a 32-bit float depth near z, as
  // glPolygonOffset takes them.
  float z = gl_FragCoord.z;
  float slope = max(abs(dFdx(z)), abs(dFdy(z)));
  float resolution = exp2(floor(log2(max(z, 1e-30))) - 23.0);
  float offset = offsetFactor * slope + offsetUnits * resolution;
  nearest = z + offset;
  farthest = z - offset;
}
