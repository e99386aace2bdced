// ApertureLighting: one light seen through a point's aperture, for vtkApertureLightingInterface.
// Needs vtkSphericalCapGLSL and the defines APERTURE_SHADING and APERTURE_LAMBERT. The caps are
// prepared once, the aperture per fragment and the light per light, so that the shading itself
// needs no trigonometry outside the penumbra.

// The aperture at a fragment: the bent normal made unit (the normal n stands in where
// interpolation shortened it to nothing) and the radius clamped to pi/2. A negative radius marks
// a point without an aperture and stays negative for apertureAddLight() to see.
sphericalCapCap apertureCap(vec3 bent, float rp, vec3 n)
{
  float length = length(bent);
  return sphericalCapMakeCap(
    length > 1e-6 ? bent / length : n, clamp(rp, -1.0, 0.5 * sphericalCapPi));
}

// The cap of a sphere light of radius R whose centre is D away, asin(R/D) (pi/2 inside it), at
// least sphericalCapMinimumLightRadius; the half-angle sine and cosine come from R/D by the
// half-angle formulas.
sphericalCapCap apertureSphereLightCap(vec3 L, float R, float D)
{
  float s = D > R ? R / D : 1.0;
  float c = D > R ? sqrt((D - R) * (D + R)) / D : 0.0;
  float r = sphericalCapAtan2(s, c);
  float halfCos = sqrt(0.5 * (1.0 + c));
  const float rMin = sphericalCapMinimumLightRadius;
  return r > rMin ? sphericalCapCap(L, r, 0.5 * s / halfCos, halfCos)
                  : sphericalCapCap(L, rMin, 0.5 * rMin, 1.0);
}

// Adds a light of colour `color` (VTK's intensity times colour) to the diffuse and specular sums,
// and the part of the aperture it covers to `covered`; n is the unit normal in view coordinates.
// The highlight is VTK's (Phong, or n.L to the power for the headlight) dimmed by the part of the
// light the point sees. A point without an aperture is lit as by VTK's standard lighting.
void apertureAddLight(vec3 n, sphericalCapCap aperture, sphericalCapCap light, vec3 color,
  vec3 viewDir, float specularPower, bool headlight, inout vec3 diffuse, inout vec3 specular,
  inout float covered)
{
  vec3 L = light.axis;
  float df = max(0.0, dot(n, L));
  float transfer = df;
  float seen = 1.0;
  if (aperture.radius >= 0.0)
  {
    float coverage;
    transfer = sphericalCapShade(APERTURE_SHADING, APERTURE_LAMBERT, n, aperture, light, coverage);
    covered += coverage;
    seen = clamp(coverage / (4.0 * sphericalCapPi * light.halfSin * light.halfSin), 0.0, 1.0);
  }
  diffuse += transfer * color;
  float sf = headlight ? pow(df, specularPower)
                       : sign(df) * pow(max(0.0, dot(reflect(-L, n), viewDir)), specularPower);
  specular += sf * seen * color;
}

#ifdef APERTURE_SKY_ENVIRONMENT
// The sky from an environment: a table of its radiance integrated over caps, weighted by the
// cosine to the cap's axis, over axes (u, v in the environment's frame) and radii from 0 to pi/2
// (vtkEnvironmentMap::NewCapTable()); apertureSkyMatrix takes view coordinates into that frame.
uniform sampler3D apertureSkyTable;
uniform mat3 apertureSkyMatrix;

// What the sky adds through an aperture, as radiance reflected with albedo 1: the table's
// irradiance over pi, less the share of the aperture the lights cover, optionally weighted by
// the cosine between the normal and the bent normal (as the uniform sky is).
vec3 apertureSkyEnvironment(
  sphericalCapCap aperture, float covered, float cosNormalBent, bool cosineWeighted)
{
  vec3 d = normalize(apertureSkyMatrix * aperture.axis);
  float u = sphericalCapAtan2(d.y, d.x) / (2.0 * sphericalCapPi) + 0.5;
  float v = sphericalCapAtan2(d.z, length(d.xy)) / sphericalCapPi + 0.5;
  float radii = float(textureSize(apertureSkyTable, 0).z);
  float r = clamp(aperture.radius / (0.5 * sphericalCapPi), 0.0, 1.0);
  vec3 irradiance = texture(apertureSkyTable, vec3(u, v, (r * (radii - 1.0) + 0.5) / radii)).rgb;
  float h = aperture.halfSin;
  float area = 4.0 * sphericalCapPi * h * h;
  float open = area > 0.0 ? max(0.0, 1.0 - covered / area) : 0.0;
  return irradiance / sphericalCapPi * open *
    (cosineWeighted ? clamp(cosNormalBent, 0.0, 1.0) : 1.0);
}
#endif
