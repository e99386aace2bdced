// ApertureLighting: spherical-cap geometry for shaders, the GLSL twin of vtkSphericalCap.
// Same formulas, same input policy: angles clamped to [0, pi], NaN arguments and zero-length
// axes give empty intersections, nothing returns NaN. See vtkSphericalCap.h for the maths.

const float sphericalCapPi = 3.14159265358979;

// 2 pi (1 - cos r) without cancellation for small r.
float sphericalCapArea(float r)
{
  float s = sin(0.5 * r);
  return 4.0 * sphericalCapPi * s * s;
}

// atan(y, x) with full relative precision (0 when both are 0). Built-in atan() may be off by a
// constant 2e-5 relative (llvmpipe), which the cancellations in the lens moment amplify.
float sphericalCapAtan2(float y, float x)
{
  float ax = abs(x);
  float ay = abs(y);
  float hi = max(ax, ay);
  if (!(hi > 0.0))
  {
    return 0.0;
  }
  // Halve the angle twice, atan(t) = 2 atan(t / (1 + sqrt(1 + t^2))), then an odd series.
  float t = min(ax, ay) / hi;
  t = t / (1.0 + sqrt(1.0 + t * t));
  t = t / (1.0 + sqrt(1.0 + t * t));
  float t2 = t * t;
  float a = 4.0 * t *
    (1.0 - t2 * (1.0 / 3.0 - t2 * (1.0 / 5.0 - t2 * (1.0 / 7.0 - t2 * (1.0 / 9.0 - t2 / 11.0)))));
  if (ay > ax)
  {
    a = 0.5 * sphericalCapPi - a;
  }
  if (x < 0.0)
  {
    a = sphericalCapPi - a;
  }
  return y < 0.0 ? -a : a;
}

// Angle between unit vectors, accurate near 0 and pi.
float sphericalCapDistance(vec3 u, vec3 v)
{
  return 2.0 * sphericalCapAtan2(length(u - v), length(u + v));
}

float sphericalCapSolidAngle(float r)
{
  return isnan(r) ? 0.0 : sphericalCapArea(clamp(r, 0.0, sphericalCapPi));
}

float sphericalCapRadiusFromSolidAngle(float a)
{
  if (!(a > 0.0))
  {
    return 0.0;
  }
  float x = min(1.0, a / (4.0 * sphericalCapPi));
  return 2.0 * sphericalCapAtan2(sqrt(x), sqrt(1.0 - x));
}

// Angles at a1 and a2 and spherical excess of the triangle (a1, a2, crossing point).
void sphericalCapLensTriangle(float r1, float r2, float d,
  out float phi1, out float phi2, out float excess)
{
  // The larger radius meets d first: with a small cap on the other's rim, (r1 + r2) - d would
  // round the small radius away and the angles would no longer match the axes.
  float rBig = max(r1, r2);
  float rSmall = min(r1, r2);
  float e = d - rBig;
  float sSmall = max(0.0, 0.5 * (rSmall + e));
  float sBig = 0.5 * ((rBig - rSmall) + d);
  float sd = max(0.0, 0.5 * (rSmall - e));
  float s1 = r1 >= r2 ? sSmall : sBig;
  float s2 = r1 >= r2 ? sBig : sSmall;
  float s = 0.5 * (r1 + r2 + d);
  float sinS = sin(s);
  phi1 = 2.0 * sphericalCapAtan2(sqrt(sin(s1) * sin(sd)), sqrt(sinS * sin(s2)));
  phi2 = 2.0 * sphericalCapAtan2(sqrt(sin(s2) * sin(sd)), sqrt(sinS * sin(s1)));
  float t = tan(0.5 * s) * tan(0.5 * s1) * tan(0.5 * s2) * tan(0.5 * sd);
  excess = 4.0 * sphericalCapAtan2(sqrt(max(0.0, t)), 1.0);
}

// Solid angle of the intersection of caps of radii r1, r2 (clamped, not NaN) whose axes are d
// apart; when the boundary circles cross, also the triangle's angles (crossing = true).
float sphericalCapLensArea(float r1, float r2, float d,
  out float phi1, out float phi2, out bool crossing)
{
  phi1 = 0.0;
  phi2 = 0.0;
  crossing = false;
  float rMin = min(r1, r2);
  if (rMin <= 0.0 || d >= r1 + r2)
  {
    return 0.0;
  }
  if (d <= max(r1, r2) - rMin)
  {
    return sphericalCapArea(rMin);
  }
  if (r1 + r2 + d >= 2.0 * sphericalCapPi)
  {
    return max(0.0, sphericalCapArea(r1) + sphericalCapArea(r2) - 4.0 * sphericalCapPi);
  }
  crossing = true;
  float excess;
  sphericalCapLensTriangle(r1, r2, d, phi1, phi2, excess);
  float h1 = sin(0.5 * r1);
  float h2 = sin(0.5 * r2);
  float area = 4.0 * (phi1 * h1 * h1 + phi2 * h2 * h2) - 2.0 * excess;
  return clamp(area, 0.0, sphericalCapArea(rMin));
}

// Area and first moment of the intersection of caps (u1, r1) and (u2, r2), unit axes d apart.
float sphericalCapLens(vec3 u1, float r1, vec3 u2, float r2, float d, out vec3 moment)
{
  moment = vec3(0.0);
  float phi1, phi2;
  bool crossing;
  float area = sphericalCapLensArea(r1, r2, d, phi1, phi2, crossing);
  if (area <= 0.0)
  {
    return 0.0;
  }
  float s1 = sin(r1);
  float s2 = sin(r2);
  if (!crossing && d <= abs(r1 - r2))
  {
    float s = r1 <= r2 ? s1 : s2;
    moment = sphericalCapPi * s * s * (r1 <= r2 ? u1 : u2);
    return area;
  }
  if (!crossing)
  {
    moment = sphericalCapPi * (s1 * s1 * u1 + s2 * s2 * u2);
    return area;
  }
  // The tangents at u1 and u2 toward each other are (delta + k u1)/sin d and (-delta + k u2)/sin d,
  // delta = u2 - u1, k = 1 - cos d; grouping the delta terms keeps nearby small caps accurate.
  float w1 = s1 * cos(r1) * sin(phi1);
  float w2 = s2 * cos(r2) * sin(phi2);
  float sinD = sin(d);
  vec3 tangents = tan(0.5 * d) * (w1 * u1 + w2 * u2);
  if (sinD > 0.0)
  {
    tangents += (w1 - w2) / sinD * (u2 - u1);
  }
  moment = s1 * s1 * phi1 * u1 + s2 * s2 * phi2 * u2 - tangents;
  return area;
}

float sphericalCapIntersectionArea(float r1, float r2, float d)
{
  if (isnan(r1) || isnan(r2) || isnan(d))
  {
    return 0.0;
  }
  float phi1, phi2;
  bool crossing;
  return sphericalCapLensArea(clamp(r1, 0.0, sphericalCapPi), clamp(r2, 0.0, sphericalCapPi),
    clamp(d, 0.0, sphericalCapPi), phi1, phi2, crossing);
}

float sphericalCapIntersectionAreaSmoothstep(float r1, float r2, float d)
{
  if (isnan(r1) || isnan(r2) || isnan(d))
  {
    return 0.0;
  }
  r1 = clamp(r1, 0.0, sphericalCapPi);
  r2 = clamp(r2, 0.0, sphericalCapPi);
  d = clamp(d, 0.0, sphericalCapPi);
  float rMin = min(r1, r2);
  if (rMin <= 0.0)
  {
    return 0.0;
  }
  float x = 1.0 - (d - abs(r1 - r2)) / (2.0 * rMin);
  return sphericalCapArea(rMin) * smoothstep(0.0, 1.0, x);
}

// Unit vector along v, or false for zero-length and non-finite vectors.
bool sphericalCapUnitAxis(vec3 v, out vec3 u)
{
  float n = length(v);
  u = vec3(0.0);
  if (!(n > 0.0) || isinf(n) || isnan(n))
  {
    return false;
  }
  u = v / n;
  return true;
}

vec3 sphericalCapIntersectionMoment(vec3 a1, float r1, vec3 a2, float r2)
{
  vec3 u1, u2;
  if (isnan(r1) || isnan(r2) || !sphericalCapUnitAxis(a1, u1) || !sphericalCapUnitAxis(a2, u2))
  {
    return vec3(0.0);
  }
  vec3 moment;
  sphericalCapLens(u1, clamp(r1, 0.0, sphericalCapPi), u2, clamp(r2, 0.0, sphericalCapPi),
    sphericalCapDistance(u1, u2), moment);
  return moment;
}

// Unit centroid direction of the intersection, or vec3(0) when it is empty.
vec3 sphericalCapIntersectionCentroid(vec3 a1, float r1, vec3 a2, float r2)
{
  vec3 m = sphericalCapIntersectionMoment(a1, r1, a2, r2);
  float n = length(m);
  return n > 0.0 ? m / n : vec3(0.0);
}

float sphericalCapSphereLightIrradiance(float sigma, float theta)
{
  if (isnan(sigma) || isnan(theta))
  {
    return 0.0;
  }
  sigma = clamp(sigma, 0.0, 0.5 * sphericalCapPi);
  theta = clamp(theta, 0.0, sphericalCapPi);
  if (sigma <= 0.0)
  {
    return 0.0;
  }
  float sinSigma = sin(sigma);
  float sin2Sigma = sinSigma * sinSigma;
  float cosTheta = cos(theta);
  float sinTheta = sin(theta);
  if (cosTheta * cosTheta > sin2Sigma || sinTheta <= 0.0)
  {
    return sphericalCapPi * sin2Sigma * max(cosTheta, 0.0);
  }
  float x = cos(sigma) / sinSigma;
  float y = clamp(-x * cosTheta / sinTheta, -1.0, 1.0);
  float root = sqrt(1.0 - y * y);
  float e = (cosTheta * sphericalCapAtan2(root, y) - x * sinTheta * root) * sin2Sigma +
    sphericalCapAtan2(sinTheta * root, x);
  return max(e, 0.0);
}

float sphericalCapSphereLightCapRadius(float radius, float dist)
{
  if (!(radius > 0.0) || isnan(dist))
  {
    return 0.0;
  }
  return dist <= radius ? 0.5 * sphericalCapPi
                        : sphericalCapAtan2(radius, sqrt((dist - radius) * (dist + radius)));
}

// (cos d - cos(rp + rl)) / (cos|rp - rl| - cos(rp + rl)), clamped to [0, 1], with the cosine
// differences written as sine products so that small caps keep their precision.
float sphericalCapSimplifiedRamp(float rp, float rl, float d)
{
  float sum = rp + rl;
  if (sum >= sphericalCapPi)
  {
    float c = cos(0.5 * d) / cos(0.5 * (rp - rl));
    return clamp(c * c, 0.0, 1.0);
  }
  float den = sin(max(rp, rl)) * sin(min(rp, rl));
  if (!(den > 0.0))
  {
    return d < rp ? 1.0 : 0.0;
  }
  return clamp(sin(0.5 * (d + sum)) * sin(0.5 * (sum - d)) / den, 0.0, 1.0);
}

float sphericalCapSimplifiedShadowFactor(float rp, float rl, float d)
{
  if (isnan(rp) || isnan(rl) || isnan(d))
  {
    return 0.0;
  }
  rp = clamp(rp, 0.0, sphericalCapPi);
  rl = clamp(rl, 0.0, sphericalCapPi);
  d = clamp(d, 0.0, sphericalCapPi);
  if (rp <= 0.0)
  {
    return 0.0;
  }
  float ramp = sphericalCapSimplifiedRamp(rp, rl, d);
  float share = rl > 0.0 ? min(1.0, sphericalCapArea(rp) / sphericalCapArea(rl)) : 1.0;
  return ramp * share;
}

// Shading models and Lambert factors, as in vtkSphericalCap::Shading and ::Lambert.
const int sphericalCapExact = 0;
const int sphericalCapSmoothstep = 1;
const int sphericalCapSimplified = 2;
const int sphericalCapBentNormal = 3;
const int sphericalCapCentroid = 0;
const int sphericalCapMoment = 1;
const float sphericalCapMinimumLightRadius = 1e-4;

// The middle of the overlap of caps (l, rl) and (bent, rp) along the great circle through their
// axes, d apart: a cheap stand-in for the lens centroid.
vec3 sphericalCapOverlapMiddle(vec3 l, float rl, vec3 bent, float rp, float d)
{
  float sinD = sin(d);
  if (!(sinD > 1e-6))
  {
    return l;
  }
  float t = 0.5 * (max(-rl, d - rp) + min(rl, d + rp));
  return cos(t) * l + sin(t) * (bent - cos(d) * l) / sinD;
}

// vtkSphericalCap::LightTransfer() and, in coverage, vtkSphericalCap::LightCoverage().
float sphericalCapLightTransfer(int shading, int lambert, vec3 n, vec3 bent, float rp, vec3 l,
  float rl, out float coverage)
{
  coverage = 0.0;
  vec3 un, ub, ul;
  // An unusable normal leaves un = 0: no Lambert term, the coverage still stands.
  sphericalCapUnitAxis(n, un);
  if (isnan(rp) || isnan(rl) || !sphericalCapUnitAxis(bent, ub) || !sphericalCapUnitAxis(l, ul))
  {
    return 0.0;
  }
  rp = clamp(rp, 0.0, 0.5 * sphericalCapPi);
  rl = clamp(rl, sphericalCapMinimumLightRadius, 0.5 * sphericalCapPi);
  float d = sphericalCapDistance(ub, ul);
  float sinL = sin(rl);
  float radiance = 1.0 / (sphericalCapPi * sinL * sinL);
  if (shading == sphericalCapExact)
  {
    vec3 m;
    coverage = sphericalCapLens(ul, rl, ub, rp, d, m);
    if (lambert == sphericalCapMoment)
    {
      return max(0.0, dot(un, m)) * radiance;
    }
    float length = length(m);
    return length > 0.0 ? coverage * max(0.0, dot(un, m) / length) * radiance : 0.0;
  }
  if (shading == sphericalCapSmoothstep)
  {
    coverage = sphericalCapIntersectionAreaSmoothstep(rl, rp, d);
    return coverage * max(0.0, dot(un, sphericalCapOverlapMiddle(ul, rl, ub, rp, d))) * radiance;
  }
  if (shading == sphericalCapSimplified)
  {
    float shadow = sphericalCapSimplifiedShadowFactor(rp, rl, d);
    coverage = shadow * min(sphericalCapArea(rl), sphericalCapArea(rp));
    return shadow * max(0.0, dot(un, ul));
  }
  if (shading == sphericalCapBentNormal)
  {
    float open = sphericalCapArea(rp) / (2.0 * sphericalCapPi);
    coverage = open * sphericalCapArea(rl);
    return open * max(0.0, dot(ub, ul));
  }
  return 0.0;
}

// vtkSphericalCap::SkyTransfer().
float sphericalCapSkyTransfer(float rp, float covered, float cosNormalBent, bool cosineWeighted)
{
  if (isnan(rp) || isnan(covered) || isnan(cosNormalBent))
  {
    return 0.0;
  }
  rp = clamp(rp, 0.0, 0.5 * sphericalCapPi);
  float open = max(0.0, sphericalCapArea(rp) - max(0.0, covered)) / (2.0 * sphericalCapPi);
  return cosineWeighted ? open * clamp(cosNormalBent, 0.0, 1.0) : open;
}
