// ApertureLighting: the lights and the sky seen through a fragment's aperture, for
// vtkApertureLightingInterface. Needs vtkSphericalCap::GetGLSLConstants(), vtkSphericalCapGLSL
// and VTK's lighting uniforms first, and these defines: APERTURE_SHADING and APERTURE_LAMBERT
// (vtkSphericalCap's model and Lambert factor), APERTURE_LIGHT_COUNT, and optionally
// APERTURE_PER_TEXEL (apertures from a texture), APERTURE_SKY_ENVIRONMENT (the sky from an
// environment: through the cap, or with APERTURE_OPEN_ENVIRONMENT through the horizons' wedges
// or the masks' open cells, with APERTURE_TEXEL_ENVIRONMENT from a texture of it per texel),
// APERTURE_HORIZONS (lights and the uniform sky above per-sector horizons, with
// vtkHorizonLightingGLSL first and apertureReadHorizons() written in at its mark below) and
// APERTURE_VERTEX_LIGHTING (lights and the uniform sky evaluated per vertex, through visibility
// masks or above horizons: apertureReadVertexLighting() at its mark below reads the interpolated
// results). It also needs
// vtkApertureLightCapGLSL. The caps are prepared once, the aperture per fragment and the light
// per light, so that the shading itself needs no trigonometry outside the penumbra.
//
// main() calls apertureBeginFragment(), one light function per light (VTK names each light's
// uniforms apart: lightColor0, lightColor1, ...), then apertureEndFragment().

uniform vec3 apertureSkyColor;
uniform int apertureSkyCosine;

// Per light, in the order the renderer numbers its switched-on lights: the radius of its cap and
// the sine and cosine of its half (computed once on the CPU), and the world-space radius of a
// positional light (-1 for none).
uniform vec3 apertureLightCap[APERTURE_LIGHT_COUNT];
uniform float apertureLightWorldRadius[APERTURE_LIGHT_COUNT];

// Apertures reach the fragment shader as varyings in view coordinates, or as texture coordinates
// in the per-texel mode.
#ifdef APERTURE_PER_TEXEL
uniform sampler2D apertureTexture;
uniform mat3 apertureNormalMatrix;
in vec2 apertureUVVSOutput;
#else
in vec3 bentNormalVCVSOutput;
in float apertureRadiusVSOutput;
#endif

#ifdef APERTURE_TEXEL_ENVIRONMENT
// The environment sky through each texel's open wedges, without the lights (from the CPU).
uniform sampler2D apertureSkyTexels;
#endif

#ifdef APERTURE_HORIZONS
// View coordinates to the horizons' frame (the model's x, y and z).
uniform mat3 apertureViewToModel;
//APERTURE::Horizons::Dec
#endif

#ifdef APERTURE_VERTEX_LIGHTING
// Per light, its transfer and the solid angle of it the point sees; the sky, uniform or from the
// environment (apertureReadVertexLighting() reads them, in the lights' order, interpolated).
vec2 apertureVertexLights[APERTURE_LIGHT_COUNT];
vec3 apertureVertexSky;
int apertureVertexLightIndex;
//APERTURE::VertexLighting::Dec
#endif

// The aperture at a fragment: the bent normal made unit (the normal n stands in where
// interpolation shortened it to nothing) and the radius clamped to pi/2. A negative radius marks
// a point without an aperture and stays negative for apertureAddLight() to see.
sphericalCapCap apertureCap(vec3 bent, float rp, vec3 n)
{
  float length = length(bent);
  return sphericalCapMakeCap(
    length > 1e-6 ? bent / length : n, clamp(rp, -1.0, 0.5 * sphericalCapPi));
}

// What a fragment gathers: its unit normal, position and direction to the eye in view
// coordinates, its specular power and aperture (and horizons), and the sums over the lights (the
// diffuse and specular light, and the part of the aperture the lights cover, in solid angle and
// in the integral of n . w).
struct apertureFragment
{
  vec3 normal;
  vec3 position;
  vec3 view;
  float specularPower;
  sphericalCapCap aperture;
  vec3 diffuse;
  vec3 specular;
  float covered;
  float coveredCosine;
#ifdef APERTURE_HORIZONS
  vec3 normalModel; // the horizons themselves are the twin's horizonLightingHorizons
#endif
};

// A fragment with its aperture and no light yet; n is the unit normal in view coordinates.
apertureFragment apertureBeginFragment(vec3 n, vec3 position, float specularPower)
{
#ifdef APERTURE_PER_TEXEL
  vec4 apertureSample = texture(apertureTexture, apertureUVVSOutput);
  vec3 bent = apertureNormalMatrix * apertureSample.xyz;
  float radius = apertureSample.w;
#else
  vec3 bent = bentNormalVCVSOutput;
  float radius = apertureRadiusVSOutput;
#endif
  // Back faces see the aperture mirrored, as their normal is.
  if (gl_FrontFacing == false)
  {
    bent = -bent;
  }
  apertureFragment f;
  f.normal = n;
  f.position = position;
  f.view = normalize(-position);
  f.specularPower = specularPower;
  f.aperture = apertureCap(bent, radius, n);
  f.diffuse = vec3(0.0);
  f.specular = vec3(0.0);
  f.covered = 0.0;
  f.coveredCosine = 0.0;
#ifdef APERTURE_HORIZONS
  f.normalModel = apertureViewToModel * n;
  apertureReadHorizons();
#endif
#ifdef APERTURE_VERTEX_LIGHTING
  apertureReadVertexLighting();
#endif
  return f;
}

// Adds a light of colour `color` (VTK's intensity times colour) to the fragment's sums, and the
// part of the aperture it covers. The highlight is VTK's (Phong, or n.L to the power for the
// headlight) dimmed by the part of the light the point sees. A point without an aperture is lit
// as by VTK's standard lighting.
void apertureAddLight(inout apertureFragment f, sphericalCapCap light, vec3 color, bool headlight)
{
  vec3 n = f.normal;
  vec3 L = light.axis;
  float df = max(0.0, dot(n, L));
  float transfer = df;
  float seen = 1.0;
  if (f.aperture.radius >= 0.0)
  {
#if defined(APERTURE_VERTEX_LIGHTING)
    vec2 vertexLight =
      apertureVertexLights[min(apertureVertexLightIndex, APERTURE_LIGHT_COUNT - 1)];
    apertureVertexLightIndex += 1;
    transfer = vertexLight.x;
    float coverage = vertexLight.y;
#elif defined(APERTURE_HORIZONS)
    vec2 sums;
    transfer = horizonLightingLightTransfer(
      f.normalModel, apertureViewToModel * L, light.radius, sums);
    float coverage = sums.x;
    f.coveredCosine += sums.y;
#else
    float coverage;
    transfer =
      sphericalCapShade(APERTURE_SHADING, APERTURE_LAMBERT, n, f.aperture, light, coverage);
#endif
    f.covered += coverage;
    seen = clamp(coverage / (4.0 * sphericalCapPi * light.halfSin * light.halfSin), 0.0, 1.0);
  }
  f.diffuse += transfer * color;
  float sf = headlight
    ? pow(df, f.specularPower)
    : sign(df) * pow(max(0.0, dot(reflect(-L, n), f.view)), f.specularPower);
  f.specular += sf * seen * color;
}

// The headlight (light complexity 1) shines along the view direction; cap is its
// apertureLightCap.
void apertureHeadlight(vec3 color, vec3 cap, inout apertureFragment f)
{
  apertureAddLight(f, sphericalCapCap(vec3(0.0, 0.0, 1.0), cap.x, cap.y, cap.z), color, true);
}

// A directional light of light complexity 2 (light kits), shining along direction.
void apertureDirectionalLight(vec3 direction, vec3 color, vec3 cap, inout apertureFragment f)
{
  apertureAddLight(f, sphericalCapCap(-direction, cap.x, cap.y, cap.z), color, false);
}

// A light of light complexity 3, with VTK's uniforms of that light: a positional one gets VTK's
// attenuation and spot cone, and a world-space radius (worldRadius > 0) gives it the cap
// asin(R/D) at this fragment.
void aperturePositionalLight(vec3 direction, vec3 color, vec3 cap, int positional,
  vec3 position, vec3 attenuationCoefficients, float coneAngle, float exponent,
  float worldRadius, inout apertureFragment f)
{
  sphericalCapCap light =
    apertureLightCapAt(direction, cap, positional, position, worldRadius, f.position);
  float attenuation = 1.0;
  if (positional != 0)
  {
    float distanceVC = length(position - f.position);
    vec3 k = attenuationCoefficients;
    attenuation = 1.0 / (k.x + k.y * distanceVC + k.z * distanceVC * distanceVC);
    if (coneAngle < 90.0)
    {
      float coneDot = dot(-light.axis, direction);
      attenuation *= coneDot >= cos(radians(coneAngle)) ? pow(coneDot, exponent) : 0.0;
    }
  }
  apertureAddLight(f, light, attenuation * color, false);
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

// The fragment's colour: the sky through the part of the aperture the lights leave uncovered
// (none for a point without an aperture), then VTK's colours and opacity.
vec4 apertureEndFragment(apertureFragment f, vec3 ambientColor, vec3 diffuseColor,
  vec3 specularColor, float opacity)
{
  vec3 diffuse = f.diffuse;
  if (f.aperture.radius >= 0.0)
  {
    float cosNormalBent = dot(f.normal, f.aperture.axis);
#if defined(APERTURE_OPEN_ENVIRONMENT) && defined(APERTURE_VERTEX_LIGHTING)
    diffuse += apertureSkyColor * apertureVertexSky;
#elif defined(APERTURE_TEXEL_ENVIRONMENT)
    diffuse += apertureSkyColor * texture(apertureSkyTexels, apertureUVVSOutput).rgb *
      horizonLightingOpenShare(
        f.normalModel, vec2(f.covered, f.coveredCosine), apertureSkyCosine != 0);
#elif defined(APERTURE_OPEN_ENVIRONMENT)
    diffuse += apertureSkyColor *
      horizonLightingEnvironmentSky(
        f.normalModel, vec2(f.covered, f.coveredCosine), apertureSkyCosine != 0);
#elif defined(APERTURE_SKY_ENVIRONMENT)
    diffuse += apertureSkyColor *
      apertureSkyEnvironment(f.aperture, f.covered, cosNormalBent, apertureSkyCosine != 0);
#elif defined(APERTURE_VERTEX_LIGHTING)
    diffuse += apertureSkyColor * apertureVertexSky;
#elif defined(APERTURE_HORIZONS)
    diffuse += apertureSkyColor *
      horizonLightingSkyTransfer(
        f.normalModel, vec2(f.covered, f.coveredCosine), apertureSkyCosine != 0);
#else
    diffuse += apertureSkyColor *
      sphericalCapSkyShade(f.aperture, f.covered, cosNormalBent, apertureSkyCosine != 0);
#endif
  }
  diffuse = diffuse * diffuseColor;
  vec3 specular = f.specular * specularColor;
  return vec4(ambientColor + diffuse + specular, opacity);
}
