// ApertureLighting: the cap of a light at a point, for vtkApertureLightingInterface's fragment
// shader and, for visibility masks, its vertex shader. Needs vtkSphericalCapGLSL.

// The cap of a sphere light of radius R whose centre is D away, asin(R/D) (pi/2 inside it), as
// sphericalCapClampLightRadius() clamps it; the half-angle sine and cosine come from R/D by the
// half-angle formulas.
sphericalCapCap apertureSphereLightCap(vec3 L, float R, float D)
{
  float s = D > R ? R / D : 1.0;
  float c = D > R ? sqrt((D - R) * (D + R)) / D : 0.0;
  float r = sphericalCapAtan2(s, c);
  if (isnan(r) || r <= sphericalCapMinimumLightRadius)
  {
    return sphericalCapMakeCap(L, sphericalCapClampLightRadius(r));
  }
  float halfCos = sqrt(0.5 * (1.0 + c));
  return sphericalCapCap(L, r, 0.5 * s / halfCos, halfCos);
}

// The cap at view position `at` of a light of light complexity 3, from VTK's uniforms of that
// light and its apertureLightCap and apertureLightWorldRadius: a positional light shines from its
// position, and a world-space radius (worldRadius > 0) makes its cap asin(R/D).
sphericalCapCap apertureLightCapAt(
  vec3 direction, vec3 cap, int positional, vec3 position, float worldRadius, vec3 at)
{
  sphericalCapCap light = sphericalCapCap(-direction, cap.x, cap.y, cap.z);
  if (positional != 0)
  {
    vec3 toLight = position - at;
    float distanceVC = length(toLight);
    light.axis = toLight / distanceVC;
    if (worldRadius > 0.0)
    {
      light = apertureSphereLightCap(light.axis, worldRadius, distanceVC);
    }
  }
  return light;
}
