// ApertureLighting: the GLSL twin of vtkHorizonLighting (see that class for the conventions and
// the formulas). Needs vtkSphericalCapGLSL (for its pi and atan2), vtkHorizonLightingCodeGLSL,
// vtkHorizonLighting's GetGLSLConstants(), and HORIZON_LIGHTING_SECTORS, the number of sectors;
// HORIZON_LIGHTING_ENVIRONMENT adds the environment sky, from a wedge table.

// The horizons of the point being shaded, which the functions below read: GLSL passes arrays by
// value, and a software rasteriser copied them on every call at a greater cost than the shading.
float horizonLightingHorizons[HORIZON_LIGHTING_SECTORS];

// The horizon at an azimuth, linear between sector middles, around the circle.
float horizonLightingAt(float azimuth)
{
  float sectors = float(HORIZON_LIGHTING_SECTORS);
  float u = azimuth * sectors / (2.0 * sphericalCapPi) - 0.5;
  float k = floor(u);
  float f = u - k;
  int k0 = int(k - sectors * floor(k / sectors));
  k0 = clamp(k0, 0, HORIZON_LIGHTING_SECTORS - 1);
  int k1 = k0 + 1 == HORIZON_LIGHTING_SECTORS ? 0 : k0 + 1;
  return horizonLightingHorizons[k0] + f * (horizonLightingHorizons[k1] - horizonLightingHorizons[k0]);
}

// asin through sphericalCapAtan2, whose precision for small angles the built-in may lack.
float horizonLightingAsin(float x)
{
  return sphericalCapAtan2(x, sqrt(max(0.0, 1.0 - x * x)));
}

// The tangent plane's elevation along azimuth (c, s) for a normal taken as facing up.
float horizonLightingTangent(vec3 n, float c, float s)
{
  return sphericalCapAtan2(-(n.x * c + n.y * s), max(n.z, 1e-4));
}

// Adds one azimuth phi of a light cap, elevations [eLow, eHigh], above horizon h and the tangent
// plane, weighted by w: its solid angle (x) and its integral of n . w (y).
void horizonLightingAddMeridian(
  vec3 n, float phi, float eLow, float eHigh, float h, float w, inout vec2 sums)
{
  float c = cos(phi);
  float s = sin(phi);
  float lit = max(max(eLow, h), horizonLightingTangent(n, c, s));
  if (eHigh > lit)
  {
    float width = eHigh - lit;
    float sinWidth = sin(width);
    float horizontal = 0.5 * width + 0.5 * cos(eHigh + lit) * sinWidth;
    float vertical = 0.5 * sin(eHigh + lit) * sinWidth;
    sums.x += w * 2.0 * cos(0.5 * (eHigh + lit)) * sin(0.5 * width);
    sums.y += w * ((n.x * c + n.y * s) * horizontal + n.z * vertical);
  }
}

// The lowest (x) and highest (y) horizon that horizonLightingAt() takes over azimuths
// [phi0, phi1]: those of the sectors whose middles bracket them.
vec2 horizonLightingRange(float phi0, float phi1)
{
  float sectors = float(HORIZON_LIGHTING_SECTORS);
  float first = floor(phi0 * sectors / (2.0 * sphericalCapPi) - 0.5);
  float last = floor(phi1 * sectors / (2.0 * sphericalCapPi) - 0.5) + 1.0;
  int count = int(min(sectors, last - first + 1.0));
  int k0 = clamp(int(first - sectors * floor(first / sectors)), 0, HORIZON_LIGHTING_SECTORS - 1);
  vec2 range = vec2(horizonLightingHorizons[k0]);
  for (int i = 1; i < count; ++i)
  {
    float h = horizonLightingHorizons[(k0 + i) % HORIZON_LIGHTING_SECTORS];
    range = vec2(min(range.x, h), max(range.y, h));
  }
  return range;
}

// A light cap (unit axis l, radius rl, clamped) above the horizons and the tangent plane of the
// unit normal n: its solid angle (x) and its integral of n . w (y).
vec2 horizonLightingLightSums(vec3 n, vec3 l, float rl)
{
  float beta = horizonLightingAsin(clamp(l.z, -1.0, 1.0));
  float psi = sphericalCapAtan2(l.y, l.x);
  float sinR = sin(rl);
  float halfSin = sin(0.5 * rl);
  bool polar = abs(beta) + rl >= 0.5 * sphericalCapPi;
  float cosB = cos(beta);
  float sinB = sin(beta);
  float span = polar ? sphericalCapPi : horizonLightingAsin(min(1.0, sinR / cosB));
  vec2 range = horizonLightingRange(psi - span, psi + span);
  float facing = dot(n, l);
  if (beta + rl <= range.x || facing <= -sinR)
  {
    return vec2(0.0);
  }
  if (beta - rl >= range.y && facing >= sinR)
  {
    return vec2(4.0 * sphericalCapPi * halfSin * halfSin, sphericalCapPi * sinR * sinR * facing);
  }
  int count = polar ? horizonLightingPolarSamples : horizonLightingSamples;
  vec2 sums = vec2(0.0);
  for (int q = 0; q < count; ++q)
  {
    float theta = sphericalCapPi * (float(q) + 0.5) / float(count);
    float offset = polar ? 2.0 * theta - sphericalCapPi : span * cos(theta);
    float weight =
      polar ? 2.0 * sphericalCapPi / float(count) : span * sin(theta) * sphericalCapPi / float(count);
    float a = cosB * cos(offset);
    float sinOffset = sin(offset);
    float r = sqrt(a * a + sinB * sinB);
    float lift = 2.0 * halfSin * halfSin - cosB * cosB * sinOffset * sinOffset / (1.0 + r);
    if (lift > 0.0)
    {
      float gamma = 2.0 * horizonLightingAsin(min(1.0, sqrt(lift / (2.0 * r))));
      float delta = sphericalCapAtan2(sinB, a);
      float phi = psi + offset;
      horizonLightingAddMeridian(n, phi, max(delta - gamma, -0.5 * sphericalCapPi),
        min(delta + gamma, 0.5 * sphericalCapPi), horizonLightingAt(phi), weight, sums);
    }
  }
  return vec2(sums.x, max(0.0, sums.y));
}

// vtkHorizonLighting::LightTransfer(): the irradiance from a light of intensity 1, with the
// light's solid angle above the horizons (coverage.x) and its integral of n . w (coverage.y).
float horizonLightingLightTransfer(
  vec3 n, vec3 l, float rl, out vec2 coverage)
{
  coverage = vec2(0.0);
  float ln = length(n);
  float ll = length(l);
  if (any(isnan(n)) || any(isnan(l)) || isnan(rl) || !(ln > 0.0) || !(ll > 0.0) || isinf(ln) ||
    isinf(ll))
  {
    return 0.0;
  }
  rl = sphericalCapClampLightRadius(rl);
  coverage = horizonLightingLightSums(n / ln, l / ll, rl);
  float s = sin(rl);
  return coverage.y / (sphericalCapPi * s * s);
}

// A sector's wedge floor (elevation, its sine and cosine): the horizon h, or the tangent plane of
// the unit normal n along the sector's middle (cos, sin) where that is higher.
vec3 horizonLightingWedgeFloor(vec3 n, float h, vec2 middle)
{
  h = clamp(h, -0.5 * sphericalCapPi, 0.5 * sphericalCapPi);
  float t = -(n.x * middle.x + n.y * middle.y) / max(n.z, 1e-4);
  vec3 wedge = vec3(h, sin(h), cos(h));
  if (wedge.y < t * wedge.z)
  {
    float cosE = inversesqrt(1.0 + t * t);
    wedge = vec3(sphericalCapAtan2(t, 1.0), t * cosE, cosE);
  }
  return wedge;
}

// vtkHorizonLighting::SkyTransfer(): the sky through the sectors' open wedges less the lights'
// coverage (their sums).
float horizonLightingSkyTransfer(
  vec3 n, vec2 coverage, bool cosineWeighted)
{
  float ln = length(n);
  if (any(isnan(n)) || !(ln > 0.0) || isinf(ln) || any(isnan(coverage)))
  {
    return 0.0;
  }
  n = n / ln;
  float width = 2.0 * sphericalCapPi / float(HORIZON_LIGHTING_SECTORS);
  // The sectors' bounds and middles by rotation, without trigonometry per sector.
  vec2 step = vec2(cos(width), sin(width));
  vec2 halfStep = vec2(cos(0.5 * width), sin(0.5 * width));
  vec2 bound = vec2(1.0, 0.0);
  float open = 0.0;
  float openCosine = 0.0;
  for (int k = 0; k < HORIZON_LIGHTING_SECTORS; ++k)
  {
    vec2 next = vec2(bound.x * step.x - bound.y * step.y, bound.y * step.x + bound.x * step.y);
    vec2 middle = vec2(bound.x * halfStep.x - bound.y * halfStep.y, bound.y * halfStep.x + bound.x * halfStep.y);
    vec3 wedge = horizonLightingWedgeFloor(n, horizonLightingHorizons[k], middle);
    float e = wedge.x;
    float sinE = wedge.y;
    float cosE = wedge.z;
    float horizontal = 0.25 * sphericalCapPi - 0.5 * (e + sinE * cosE);
    open += width * (1.0 - sinE);
    openCosine += (n.x * (next.y - bound.y) + n.y * (bound.x - next.x)) * horizontal +
      n.z * width * 0.5 * cosE * cosE;
    bound = next;
  }
  return cosineWeighted ? max(0.0, openCosine - coverage.y) / sphericalCapPi
                        : max(0.0, open - coverage.x) / (2.0 * sphericalCapPi);
}

// vtkHorizonLighting::OpenShare(): the share of the open wedges the lights leave.
float horizonLightingOpenShare(vec3 n, vec2 coverage, bool cosineWeighted)
{
  float all = cosineWeighted ? horizonLightingSkyTransfer(n, vec2(0.0), true) * sphericalCapPi
                             : horizonLightingSkyTransfer(n, vec2(0.0), false) * 2.0 * sphericalCapPi;
  float lost = cosineWeighted ? coverage.y : coverage.x;
  return all > 0.0 && !any(isnan(coverage)) ? max(0.0, 1.0 - lost / all) : 0.0;
}

#ifdef HORIZON_LIGHTING_ENVIRONMENT
// vtkEnvironmentMap::NewWedgeTable() in the horizons' frame: azimuths + 1 columns, elevations
// rows, the three axes as layers, filtered linearly.
uniform sampler3D horizonLightingSkyWedges;

// n . (the wedge table at azimuth phi and elevation e).
vec3 horizonLightingWedgeAt(vec3 n, float phi, float e)
{
  vec3 size = vec3(textureSize(horizonLightingSkyWedges, 0));
  vec2 uv = vec2(phi / (2.0 * sphericalCapPi) * (size.x - 1.0),
    (e + 0.5 * sphericalCapPi) / sphericalCapPi * (size.y - 1.0));
  uv = (clamp(uv, vec2(0.0), size.xy - 1.0) + 0.5) / size.xy;
  return n.x * texture(horizonLightingSkyWedges, vec3(uv, 0.5 / 3.0)).rgb +
    n.y * texture(horizonLightingSkyWedges, vec3(uv, 1.5 / 3.0)).rgb +
    n.z * texture(horizonLightingSkyWedges, vec3(uv, 2.5 / 3.0)).rgb;
}

// vtkHorizonLighting::EnvironmentSkyTransfer(): the environment through the sectors' open wedges,
// scaled by the share of them the lights leave (their sums).
vec3 horizonLightingEnvironmentSky(vec3 n, vec2 coverage, bool cosineWeighted)
{
  float ln = length(n);
  if (any(isnan(n)) || !(ln > 0.0) || isinf(ln) || any(isnan(coverage)))
  {
    return vec3(0.0);
  }
  n = n / ln;
  float width = 2.0 * sphericalCapPi / float(HORIZON_LIGHTING_SECTORS);
  vec3 sum = vec3(0.0);
  for (int k = 0; k < HORIZON_LIGHTING_SECTORS; ++k)
  {
    float middle = (float(k) + 0.5) * width;
    float e = horizonLightingWedgeFloor(n, horizonLightingHorizons[k], vec2(cos(middle), sin(middle))).x;
    sum += horizonLightingWedgeAt(n, float(k + 1) * width, e) - horizonLightingWedgeAt(n, float(k) * width, e);
  }
  return max(sum, vec3(0.0)) * horizonLightingOpenShare(n, coverage, cosineWeighted) / sphericalCapPi;
}
#endif
