// ApertureLighting: computeLighting() of VTK's GPU volume ray caster, shaded by each sample's
// aperture, for vtkApertureVolumeMapper. It takes the place of VTK's lighting declaration, after
// vtkSphericalCap::GetGLSLConstants() and vtkSphericalCapGLSL, with APERTURE_SHADING (the
// vtkSphericalCap model: EXACT or SMOOTHSTEP) and, where they apply, APERTURE_GRADIENT_OPACITY
// (the volume property has a gradient opacity), APERTURE_SKY_ENVIRONMENT (an HDR sky) and
// APERTURE_INTERPOLATE_LIGHT (the eight voxels' light blended) defined.
//
// A sample inside a medium has no surface to turn toward a light: it gets the part of each
// light's cap that its aperture holds (the light's visible share, 1 in free space, as
// vtkVolumeApertureReference's irradiance is), and of a uniform sky the aperture's share of the
// whole sphere.

// The uniforms come from vtkApertureVolumeMapper as the shader property's custom uniforms,
// declared ahead of this code: the apertures (apertureVolume, RGBA8: the bent normal as
// (n + 1)/2, the radius as r/pi), read at the volume's texture coordinates times
// apertureTextureScale plus apertureTextureShift (the aperture grid may be coarser, of
// apertureGridSize voxels), read apertureSurfaceOffset aperture voxels toward the eye; up to 8
// lights (apertureLightCount): toward each in the volume's data axes (apertureLightAxis), its cap
// (apertureLightCap: radius, and the sine and cosine of half of it) and its colour times
// intensity times the property's diffuse (apertureLightColor); the sky's colour times the
// property's ambient (apertureSkyColor). With APERTURE_SKY_ENVIRONMENT defined, an environment's
// radiance over caps (apertureSkyTable, vtkEnvironmentMap::NewCapRadianceTable(): axes u, v in
// the environment's frame, radii 0 to pi) and the matrix from the data axes to that frame
// (apertureSkyMatrix).

#ifdef APERTURE_SKY_ENVIRONMENT
// The environment's radiance over the aperture, over the whole sphere's 4 pi: the uniform sky's
// A / 4 pi for an environment of radiance 1.
vec3 apertureSkyShare(sphericalCapCap aperture)
{
  vec3 d = normalize(apertureSkyMatrix * aperture.axis);
  float u = sphericalCapAtan2(d.y, d.x) / (2.0 * sphericalCapPi) + 0.5;
  float v = sphericalCapAtan2(d.z, length(d.xy)) / sphericalCapPi + 0.5;
  float radii = float(textureSize(apertureSkyTable, 0).z);
  float r = clamp(aperture.radius / sphericalCapPi, 0.0, 1.0);
  vec3 radiance = texture(apertureSkyTable, vec3(u, v, (r * (radii - 1.0) + 0.5) / radii)).rgb;
  return radiance / (4.0 * sphericalCapPi);
}
#else
vec3 apertureSkyShare(sphericalCapCap aperture)
{
  return vec3(aperture.halfSin * aperture.halfSin);
}
#endif

// The share of a light's cap that falls within the aperture. Most samples see a light whole or
// not at all: those are told from the half chord between the axes, without an angle.
float apertureLightShare(sphericalCapCap aperture, sphericalCapCap light)
{
  float hc = 0.5 * length(aperture.axis - light.axis);
  float hp = aperture.halfSin;
  float cp = aperture.halfCos;
  float hl = light.halfSin;
  float cl = light.halfCos;
  if (aperture.radius + light.radius < sphericalCapPi && hc >= hp * cl + cp * hl)
  {
    return 0.0; // d >= rp + rl
  }
  if (light.radius <= aperture.radius && hc <= hp * cl - cp * hl)
  {
    return 1.0; // d <= rp - rl
  }
  float hs = 0.5 * length(aperture.axis + light.axis);
  float d = 2.0 * sphericalCapAtan2(hc, hs);
  float areaL = 4.0 * sphericalCapPi * hl * hl;
  if (APERTURE_SHADING == sphericalCapSmoothstep)
  {
    return sphericalCapIntersectionAreaSmoothstep(aperture.radius, light.radius, d) / areaL;
  }
  vec3 moment;
  int lensCase = sphericalCapLensCase(aperture.radius, light.radius, d);
  return sphericalCapLens(lensCase, aperture, light, hc, hs, moment) / areaL;
}

// The light one aperture voxel, as the texture holds it, lets through.
vec3 apertureLight(vec4 stored)
{
  vec3 bent = stored.xyz * 2.0 - 1.0;
  float length = length(bent);
  sphericalCapCap aperture = sphericalCapMakeCap(
    length > 1e-3 ? bent / length : vec3(0.0, 0.0, 1.0), stored.w * sphericalCapPi);
  vec3 light = apertureSkyColor * apertureSkyShare(aperture);
  for (int i = 0; i < apertureLightCount; ++i)
  {
    vec3 cap = apertureLightCap[i];
    light += apertureLightColor[i] *
      apertureLightShare(aperture, sphericalCapCap(apertureLightAxis[i], cap.x, cap.y, cap.z));
  }
  return light;
}

#ifdef APERTURE_INTERPOLATE_LIGHT
// The light of the eight aperture voxels about `at`, trilinear: between a wide cap and a narrow
// one the light goes from one's to the other's, where an interpolated cap of middle size would
// still hold a small light whole.
vec3 apertureSampleLight(vec3 at)
{
  vec3 grid = at * apertureGridSize - 0.5;
  vec3 base = floor(grid);
  vec3 w = grid - base;
  ivec3 last = ivec3(apertureGridSize) - 1;
  vec3 light = vec3(0.0);
  for (int c = 0; c < 8; ++c)
  {
    ivec3 corner = ivec3(c & 1, (c >> 1) & 1, c >> 2);
    vec3 axisWeights = mix(1.0 - w, w, vec3(corner));
    float weight = axisWeights.x * axisWeights.y * axisWeights.z;
    if (weight > 0.0)
    {
      ivec3 texel = clamp(ivec3(base) + corner, ivec3(0), last);
      light += weight * apertureLight(texelFetch(apertureVolume, texel, 0));
    }
  }
  return light;
}
#else
vec3 apertureSampleLight(vec3 at)
{
  return apertureLight(texture(apertureVolume, at));
}
#endif

vec4 computeLighting(vec4 color, int component, float label)
{
  // Toward the eye (by default one aperture voxel): the surface layer of opaque matter takes the
  // light of its outside, as the eye sees it, instead of banding with the depth a ray stops at in
  // the layer.
  vec3 toEye = -g_dirStep * apertureTextureScale * apertureGridSize;
  float toEyeLength = length(toEye);
  vec3 at = g_dataPos * apertureTextureScale + apertureTextureShift;
  if (toEyeLength > 0.0)
  {
    at += apertureSurfaceOffset * toEye / (toEyeLength * apertureGridSize);
  }
  vec4 finalColor = vec4(color.rgb * apertureSampleLight(at), color.a);
#ifdef APERTURE_GRADIENT_OPACITY
  vec4 gradient = computeGradient(g_dataPos, component, in_volume[0], 0);
  if (gradient.w >= 0.0 && label == 0.0)
  {
    finalColor.a *= computeGradientOpacity(gradient);
  }
#endif
  return finalColor;
}
