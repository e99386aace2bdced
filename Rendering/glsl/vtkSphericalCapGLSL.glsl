// ApertureLighting: spherical-cap geometry for shaders, the GLSL twin of vtkSphericalCap.
// Same formulas, same input policy: angles clamped to [0, pi], NaN arguments and zero-length
// axes give empty intersections, nothing returns NaN. See vtkSphericalCap.h for the maths.
// Needs vtkSphericalCap::GetGLSLConstants() first: the shading models, the Lambert factors and
// the light-radius bounds come from the C++ class, so that the two cannot drift apart.

const float sphericalCapPi = 3.14159265358979;

// A software rasteriser's built-in trigonometry (llvmpipe's) reduces any argument's range and
// costs as much as all the rest of the shading, and its atan() is off by a constant 2e-5
// relative, which the cancellations in the lens moment amplify; NVIDIA's sine is exact only to
// 1e-7 absolute, a thousandth of a small cap's: the shading uses these minimax polynomials
// instead. NVIDIA's compiler also folds !(x > 0.0) into x <= 0.0, which NaN passes (GLSL leaves
// NaN comparisons unspecified): NaN is tested with isnan().

// sin(x) for |x| <= pi/2 (relative error 5e-9).
float sphericalCapSin(float x)
{
  float u = x * x;
  float p = u * 2.60190307e-06 - 0.000198074187;
  p = p * u + 0.00833302514;
  p = p * u - 0.166666567;
  return x * (p * u + 0.999999995);
}

// sin(x) for 0 <= x <= pi, by sin(x) = sin(pi - x): relative precision near both ends, where a
// GPU's built-in sine may have an absolute one only (NVIDIA's: 1e-7 off at sin(1e-5)).
float sphericalCapSinToPi(float x)
{
  return sphericalCapSin(x <= 0.5 * sphericalCapPi ? x : sphericalCapPi - x);
}

// atan(y, x) with full relative precision (0 when both are 0; relative error 1.5e-8 before
// rounding).
float sphericalCapAtan2(float y, float x)
{
  float ax = abs(x);
  float ay = abs(y);
  float hi = max(ax, ay);
  if (isnan(hi) || hi <= 0.0)
  {
    return 0.0;
  }
  float t = min(ax, ay) / hi;
  float u = t * t;
  // atan(t) = t P(t^2) on [0, 1], by Horner's rule.
  float p = u * 0.00284988906 - 0.016068628;
  p = p * u + 0.0426915203;
  p = p * u - 0.0750429488;
  p = p * u + 0.106409343;
  p = p * u - 0.142036446;
  p = p * u + 0.199926194;
  p = p * u - 0.333330733;
  float a = t * (p * u + 0.999999985);
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

// 2 pi (1 - cos r) without cancellation for small r, for r in [0, pi].
float sphericalCapArea(float r)
{
  float s = sphericalCapSin(0.5 * r);
  return 4.0 * sphericalCapPi * s * s;
}

float sphericalCapSolidAngle(float r)
{
  return isnan(r) ? 0.0 : sphericalCapArea(clamp(r, 0.0, sphericalCapPi));
}

float sphericalCapRadiusFromSolidAngle(float a)
{
  if (isnan(a) || a <= 0.0)
  {
    return 0.0;
  }
  float x = min(1.0, a / (4.0 * sphericalCapPi));
  return 2.0 * sphericalCapAtan2(sqrt(x), sqrt(1.0 - x));
}

// A cap ready for the shading equations: unit axis, radius, and the sine and cosine of half the
// radius, from which the addition formulas give every other angle without trigonometry.
struct sphericalCapCap
{
  vec3 axis;
  float radius;
  float halfSin;
  float halfCos;
};

// A cap of radius r in [0, pi].
sphericalCapCap sphericalCapMakeCap(vec3 axis, float r)
{
  float h = sphericalCapSin(0.5 * r);
  return sphericalCapCap(axis, r, h, sqrt(max(0.0, 1.0 - h * h)));
}

// The spherical triangle (a1, a2, P), P where the two boundary circles cross, for caps c1, c2
// whose axes are d apart, given the half chord hc = sin(d/2) and half sum hs = cos(d/2): the
// angles phi1 at a1 and phi2 at a2 (half-angle formulas keep thin triangles accurate), their sines
// (algebraic, from the half-angle tangents) and the spherical excess, from the smaller radius r, d
// and the angle phi between them: tan(E/2) = tan(r/2) tan(d/2) sin phi / (1 + tan(r/2) tan(d/2)
// cos phi). The sines of the half-perimeter s and of s - r1, s - r2, s - d come from the
// half-angle sines and cosines by the addition formulas, the larger radius meeting d/2 first:
// with a small cap on the other's rim, that difference is what is left when the small radius is
// added back.
void sphericalCapLensTriangle(sphericalCapCap c1, sphericalCapCap c2, float hc, float hs,
  out float phi1, out float phi2, out float sinPhi1, out float sinPhi2, out float excess)
{
  bool firstBig = c1.radius >= c2.radius;
  float hB = firstBig ? c1.halfSin : c2.halfSin;
  float cB = firstBig ? c1.halfCos : c2.halfCos;
  float hS = firstBig ? c2.halfSin : c1.halfSin;
  float cS = firstBig ? c2.halfCos : c1.halfCos;
  // e = d/2 - rBig/2, f = d/2 + rBig/2, g = (rBig - rSmall)/2.
  float sinE = hc * cB - hs * hB;
  float cosE = hs * cB + hc * hB;
  float sinF = hc * cB + hs * hB;
  float cosF = hs * cB - hc * hB;
  float sinG = hB * cS - cB * hS;
  float cosG = cB * cS + hB * hS;
  float sinSmall = max(0.0, hS * cosE + cS * sinE);
  float sinDiff = max(0.0, hS * cosE - cS * sinE);
  float sinBig = max(0.0, hc * cosG + hs * sinG);
  float sinS = max(0.0, hS * cosF + cS * sinF);
  float sin1 = firstBig ? sinSmall : sinBig;
  float sin2 = firstBig ? sinBig : sinSmall;
  float y1 = sqrt(sin1 * sinDiff);
  float x1 = sqrt(sinS * sin2);
  float y2 = sqrt(sin2 * sinDiff);
  float x2 = sqrt(sinS * sin1);
  phi1 = 2.0 * sphericalCapAtan2(y1, x1);
  phi2 = 2.0 * sphericalCapAtan2(y2, x2);
  float n1 = x1 * x1 + y1 * y1;
  float n2 = x2 * x2 + y2 * y2;
  sinPhi1 = n1 > 0.0 ? 2.0 * x1 * y1 / n1 : 0.0;
  sinPhi2 = n2 > 0.0 ? 2.0 * x2 * y2 / n2 : 0.0;
  // The excess from the smaller cap's side: tan(r/2) of the larger one may be huge.
  float xs = firstBig ? x2 : x1;
  float ys = firstBig ? y2 : y1;
  float ns = xs * xs + ys * ys;
  float sinPhi = firstBig ? sinPhi2 : sinPhi1;
  float cosPhi = ns > 0.0 ? (xs * xs - ys * ys) / ns : 1.0;
  float t = hS / cS * (hc / hs);
  excess = 2.0 * sphericalCapAtan2(t * sinPhi, 1.0 + t * cosPhi);
}

// How caps of radii r1, r2 with axes d apart meet.
const int sphericalCapDisjoint = 0;
const int sphericalCapNested = 1;    // one inside the other
const int sphericalCapComplements = 2; // the complements are disjoint: the union is the sphere
const int sphericalCapCrossing = 3;

int sphericalCapLensCase(float r1, float r2, float d)
{
  float rMin = min(r1, r2);
  if (rMin <= 0.0 || d >= r1 + r2)
  {
    return sphericalCapDisjoint;
  }
  if (d <= max(r1, r2) - rMin)
  {
    return sphericalCapNested;
  }
  return r1 + r2 + d >= 2.0 * sphericalCapPi ? sphericalCapComplements : sphericalCapCrossing;
}

// Area and first moment of the intersection of caps c1 and c2, which meet as lensCase, their unit
// axes d apart with half chord hc = sin(d/2) and half sum hs = cos(d/2).
float sphericalCapLens(
  int lensCase, sphericalCapCap c1, sphericalCapCap c2, float hc, float hs, out vec3 moment)
{
  moment = vec3(0.0);
  if (lensCase == sphericalCapDisjoint)
  {
    return 0.0;
  }
  float h1 = c1.halfSin;
  float h2 = c2.halfSin;
  float s1 = 2.0 * h1 * c1.halfCos; // sin r
  float s2 = 2.0 * h2 * c2.halfCos;
  vec3 u1 = c1.axis;
  vec3 u2 = c2.axis;
  if (lensCase == sphericalCapNested)
  {
    // The moment of a cap (a, r) is pi sin^2 r a.
    bool first = c1.radius <= c2.radius;
    float s = first ? s1 : s2;
    float h = first ? h1 : h2;
    moment = sphericalCapPi * s * s * (first ? u1 : u2);
    return 4.0 * sphericalCapPi * h * h;
  }
  if (lensCase == sphericalCapComplements)
  {
    moment = sphericalCapPi * (s1 * s1 * u1 + s2 * s2 * u2);
    return max(0.0, 4.0 * sphericalCapPi * (h1 * h1 + h2 * h2 - 1.0));
  }
  // Tovchigrechko & Vakser: A = 2[pi - psi - phi1 cos r1 - phi2 cos r2], rearranged as two
  // sectors minus the quadrilateral (a1, P, a2, P'): 4 phik sin^2(rk/2) - 2E, without cancellation.
  float phi1, phi2, sinPhi1, sinPhi2, excess;
  sphericalCapLensTriangle(c1, c2, hc, hs, phi1, phi2, sinPhi1, sinPhi2, excess);
  float area = clamp(4.0 * (phi1 * h1 * h1 + phi2 * h2 * h2) - 2.0 * excess, 0.0,
    4.0 * sphericalCapPi * min(h1 * h1, h2 * h2));
  // The tangents at u1 and u2 toward each other are (delta + k u1)/sin d and (-delta + k u2)/sin d,
  // delta = u2 - u1, k = 1 - cos d; grouping the delta terms keeps nearby small caps accurate.
  float w1 = s1 * (1.0 - 2.0 * h1 * h1) * sinPhi1;
  float w2 = s2 * (1.0 - 2.0 * h2 * h2) * sinPhi2;
  float sinD = 2.0 * hc * hs;
  vec3 tangents = (hc / hs) * (w1 * u1 + w2 * u2);
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
  r1 = clamp(r1, 0.0, sphericalCapPi);
  r2 = clamp(r2, 0.0, sphericalCapPi);
  d = clamp(d, 0.0, sphericalCapPi);
  // The lens's area does not depend on where its axes are.
  vec3 moment;
  return sphericalCapLens(sphericalCapLensCase(r1, r2, d),
    sphericalCapMakeCap(vec3(0.0, 0.0, 1.0), r1), sphericalCapMakeCap(vec3(sin(d), 0.0, cos(d)), r2),
    sin(0.5 * d), cos(0.5 * d), moment);
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
  if (isnan(n) || n <= 0.0 || isinf(n))
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
  float hc = 0.5 * length(u1 - u2);
  float hs = 0.5 * length(u1 + u2);
  r1 = clamp(r1, 0.0, sphericalCapPi);
  r2 = clamp(r2, 0.0, sphericalCapPi);
  vec3 moment;
  sphericalCapLens(sphericalCapLensCase(r1, r2, 2.0 * sphericalCapAtan2(hc, hs)),
    sphericalCapMakeCap(u1, r1), sphericalCapMakeCap(u2, r2), hc, hs, moment);
  return moment;
}

// Unit centroid direction of the intersection, or vec3(0) when it is empty.
vec3 sphericalCapIntersectionCentroid(vec3 a1, float r1, vec3 a2, float r2)
{
  vec3 m = sphericalCapIntersectionMoment(a1, r1, a2, r2);
  float n = length(m);
  float scale = min(sphericalCapSolidAngle(r1), sphericalCapSolidAngle(r2));
  return n > sphericalCapCentroidTolerance * scale ? m / n : vec3(0.0);
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
  float sinSigma = sphericalCapSin(sigma);
  float sin2Sigma = sinSigma * sinSigma;
  float cosTheta = sphericalCapSin(0.5 * sphericalCapPi - theta);
  float sinTheta = sphericalCapSinToPi(theta);
  if (cosTheta * cosTheta > sin2Sigma || sinTheta <= 0.0)
  {
    return sphericalCapPi * sin2Sigma * max(cosTheta, 0.0);
  }
  float x = sphericalCapSin(0.5 * sphericalCapPi - sigma) / sinSigma;
  float y = clamp(-x * cosTheta / sinTheta, -1.0, 1.0);
  float root = sqrt(1.0 - y * y);
  float e = (cosTheta * sphericalCapAtan2(root, y) - x * sinTheta * root) * sin2Sigma +
    sphericalCapAtan2(sinTheta * root, x);
  return max(e, 0.0);
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
  float den = sphericalCapSinToPi(max(rp, rl)) * sphericalCapSinToPi(min(rp, rl));
  if (isnan(den) || den <= 0.0)
  {
    return d < rp ? 1.0 : 0.0;
  }
  // (d + sum)/2 lies in [0, pi) and (sum - d)/2 in (-pi/2, pi/2).
  return clamp(sphericalCapSinToPi(0.5 * (d + sum)) * sphericalCapSin(0.5 * (sum - d)) / den,
    0.0, 1.0);
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

// vtkSphericalCap::ClampLightRadius(): a light radius as the shading uses it. NaN is the
// caller's to test.
float sphericalCapClampLightRadius(float rl)
{
  // As in C++: NaN gets the smallest radius (clamp() leaves NaN undefined).
  return rl > sphericalCapMinimumLightRadius ? min(rl, sphericalCapMaximumLightRadius)
                                             : sphericalCapMinimumLightRadius;
}

// The middle of the overlap of crossing caps, light and aperture, along the great circle through
// their axes, which are d apart with half chord hc and half sum hs: a cheap stand-in for the lens
// centroid. Crossing caps overlap from d - rp to rl along the circle, measured from the light's
// axis; the middle, t = d/2 - rp/2 + rl/2, comes from the half-angle sines by the addition formulas.
vec3 sphericalCapOverlapMiddle(sphericalCapCap light, sphericalCapCap aperture, float hc, float hs)
{
  float sinD = 2.0 * hc * hs;
  if (isnan(sinD) || sinD <= 1e-6)
  {
    return light.axis;
  }
  float sinX = hc * aperture.halfCos - hs * aperture.halfSin; // x = d/2 - rp/2
  float cosX = hs * aperture.halfCos + hc * aperture.halfSin;
  float sinT = sinX * light.halfCos + cosX * light.halfSin;
  float cosT = cosX * light.halfCos - sinX * light.halfSin;
  float cosD = 1.0 - 2.0 * hc * hc;
  return cosT * light.axis + sinT * (aperture.axis - cosD * light.axis) / sinD;
}

// vtkSphericalCap::LightTransfer() and, in coverage, vtkSphericalCap::LightCoverage(), for a unit
// (or zero) normal un and caps whose radii are clamped (rp <= pi/2, rl by
// sphericalCapClampLightRadius()). Everything derives from the half-angle sines and cosines of
// the two radii and the half chord between the axes, sin(d/2), which also classifies the caps
// (cosines near 1 cannot tell nearly equal small caps apart), and only crossing caps, the
// penumbra, need angles at all.
// Shaders that prepare their caps once per fragment call this directly.
float sphericalCapShade(int shading, int lambert, vec3 un, sphericalCapCap aperture,
  sphericalCapCap light, out float coverage)
{
  coverage = 0.0;
  vec3 ub = aperture.axis;
  vec3 ul = light.axis;
  float hp = aperture.halfSin;
  float cp = aperture.halfCos;
  float hl = light.halfSin;
  float cl = light.halfCos;
  float areaP = 4.0 * sphericalCapPi * hp * hp;
  float areaL = 4.0 * sphericalCapPi * hl * hl;
  if (shading == sphericalCapBentNormal)
  {
    float open = 2.0 * hp * hp;
    coverage = open * areaL;
    return open * max(0.0, dot(ub, ul));
  }

  // sin((rp + rl)/2) and sin(|rp - rl|/2) by the addition formulas.
  float halfChord = 0.5 * length(ub - ul);
  float halfSum = 0.5 * length(ub + ul);
  float sinHalfSum = hp * cl + cp * hl;
  bool disjoint = aperture.radius <= 0.0 || halfChord >= sinHalfSum;
  bool nested = !disjoint && halfChord <= abs(hp * cl - cp * hl);
  if (shading == sphericalCapSimplified)
  {
    // The ramp of sphericalCapSimplifiedShadowFactor: sin((s + d)/2) sin((s - d)/2) over
    // sin rp sin rl, s = rp + rl, with sin(a + b) sin(a - b) = sin^2 a - sin^2 b.
    float ramp = (sinHalfSum * sinHalfSum - halfChord * halfChord) / (4.0 * hp * cp * hl * cl);
    float shadow = disjoint ? 0.0 : min(1.0, areaP / areaL) * (nested ? 1.0 : clamp(ramp, 0.0, 1.0));
    coverage = shadow * min(areaL, areaP);
    return shadow * max(0.0, dot(un, ul));
  }
  if (disjoint || (shading != sphericalCapExact && shading != sphericalCapSmoothstep))
  {
    return 0.0;
  }
  // 1/(pi sin^2 rl), sin rl = 2 hl cl.
  float radiance = 1.0 / (4.0 * sphericalCapPi * hl * hl * cl * cl);
  if (nested)
  {
    // The smaller cap lies in the other: the lens is that cap, its centroid that cap's axis; its
    // moment is pi sin^2 r times the axis.
    bool lightInside = light.radius <= aperture.radius;
    float h = lightInside ? hl : hp;
    float c = lightInside ? cl : cp;
    coverage = lightInside ? areaL : areaP;
    float factor = (shading == sphericalCapExact && lambert == sphericalCapMoment)
      ? 4.0 * sphericalCapPi * h * h * c * c : coverage;
    return factor * max(0.0, dot(un, lightInside ? ul : ub)) * radiance;
  }
  if (shading == sphericalCapExact)
  {
    vec3 m;
    coverage = sphericalCapLens(sphericalCapCrossing, light, aperture, halfChord, halfSum, m);
    if (lambert == sphericalCapMoment)
    {
      return max(0.0, dot(un, m)) * radiance;
    }
    float length = length(m);
    return length > 0.0 ? coverage * max(0.0, dot(un, m) / length) * radiance : 0.0;
  }
  float d = 2.0 * sphericalCapAtan2(halfChord, halfSum);
  float rp = aperture.radius;
  float rl = light.radius;
  float x = 1.0 - (d - abs(rp - rl)) / (2.0 * min(rp, rl));
  coverage = min(areaP, areaL) * smoothstep(0.0, 1.0, x);
  return coverage * max(0.0, dot(un, sphericalCapOverlapMiddle(light, aperture, halfChord, halfSum))) *
    radiance;
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
  return sphericalCapShade(shading, lambert, un,
    sphericalCapMakeCap(ub, clamp(rp, 0.0, 0.5 * sphericalCapPi)),
    sphericalCapMakeCap(ul, sphericalCapClampLightRadius(rl)),
    coverage);
}

// vtkSphericalCap::SkyTransfer() for an aperture cap (radius clamped to [0, pi/2]).
float sphericalCapSkyShade(
  sphericalCapCap aperture, float covered, float cosNormalBent, bool cosineWeighted)
{
  float h = aperture.halfSin;
  float open = max(0.0, 4.0 * sphericalCapPi * h * h - max(0.0, covered)) / (2.0 * sphericalCapPi);
  return cosineWeighted ? open * clamp(cosNormalBent, 0.0, 1.0) : open;
}

// vtkSphericalCap::SkyTransfer().
float sphericalCapSkyTransfer(float rp, float covered, float cosNormalBent, bool cosineWeighted)
{
  if (isnan(rp) || isnan(covered) || isnan(cosNormalBent))
  {
    return 0.0;
  }
  return sphericalCapSkyShade(
    sphericalCapMakeCap(vec3(0.0), clamp(rp, 0.0, 0.5 * sphericalCapPi)), covered, cosNormalBent,
    cosineWeighted);
}
