// ApertureLighting: the GLSL twin of vtkVisibilityMask (see that class for the cells and the
// formulas). Needs vtkSphericalCapGLSL (for its pi and atan2), vtkVisibilityMask's
// GetGLSLConstants(), VISIBILITY_MASK_SIDE (the grid's side; side² cells) and the mask being
// shaded in visibilityMaskWords (cell k at bit k % 32 of word k / 32). The sky takes the mask's
// open sums (vtkVisibilityMask::OpenSums()), which do not depend on the lights, from its caller.

const int visibilityMaskCells = VISIBILITY_MASK_SIDE * VISIBILITY_MASK_SIDE;
uint visibilityMaskWords[(visibilityMaskCells + 31) / 32];

// Duff et al.'s tangent frame of a unit normal.
void visibilityMaskFrame(vec3 n, out vec3 t, out vec3 b)
{
  float sign = n.z >= 0.0 ? 1.0 : -1.0;
  float a = -1.0 / (sign + n.z);
  float c = n.x * n.y * a;
  t = vec3(1.0 + sign * n.x * n.x * a, sign * c, -sign * n.x);
  b = vec3(c, sign + n.y * n.y * a, -n.y);
}

// The concentric map from the unit disk back to the square [-1, 1]^2: the larger coordinate's
// sign gives the square's side, the angle from it (within +-pi/4) the position along that side.
vec2 visibilityMaskDiskToSquare(vec2 p)
{
  bool wide = abs(p.x) >= abs(p.y);
  float big = wide ? p.x : p.y;
  float small = wide ? p.y : p.x;
  float r = length(p);
  float major = sign(big) * r;
  float minor = r * sphericalCapAtan2(small, abs(big)) / (0.25 * sphericalCapPi);
  return wide ? vec2(major, minor) : vec2(minor, major);
}

// The cell of unit direction w in the frame (t, b, n), or -1 below its plane.
int visibilityMaskCellInFrame(vec3 t, vec3 b, vec3 n, vec3 w)
{
  float z = dot(w, n);
  if (isnan(z) || z < 0.0)
  {
    return -1;
  }
  vec2 square = visibilityMaskDiskToSquare(vec2(dot(w, t), dot(w, b)) * inversesqrt(1.0 + min(1.0, z)));
  float side = float(VISIBILITY_MASK_SIDE);
  int i = clamp(int(0.5 * (square.x + 1.0) * side), 0, VISIBILITY_MASK_SIDE - 1);
  int j = clamp(int(0.5 * (square.y + 1.0) * side), 0, VISIBILITY_MASK_SIDE - 1);
  return i + VISIBILITY_MASK_SIDE * j;
}

// The cell of unit direction w around unit normal n, or -1 below the tangent plane.
int visibilityMaskCellOf(vec3 n, vec3 w)
{
  vec3 t;
  vec3 b;
  visibilityMaskFrame(n, t, b);
  return visibilityMaskCellInFrame(t, b, n, w);
}

bool visibilityMaskIsOpen(int cell)
{
  return ((visibilityMaskWords[cell / 32] >> uint(cell % 32)) & 1u) != 0u;
}

// vtkVisibilityMask::LightSamples(): 8 per eighth of a cell the cap covers, 8 to 64.
int visibilityMaskLightSamples(float rl)
{
  float halfSin = sin(0.5 * rl);
  float eighths = 8.0 * 4.0 * sphericalCapPi * halfSin * halfSin /
    (2.0 * sphericalCapPi / float(visibilityMaskCells));
  return visibilityMaskSampleStep *
    int(min(float(visibilityMaskMaximumSamples / visibilityMaskSampleStep), max(1.0, ceil(eighths))));
}

// vtkVisibilityMask::LightTransfer(): the irradiance from a light of intensity 1 through the
// open cells, with the light's solid angle there (coverage.x) and its integral of n . w
// (coverage.y).
float visibilityMaskLightTransfer(vec3 n, vec3 l, float rl, out vec2 coverage)
{
  coverage = vec2(0.0);
  float ln = length(n);
  float ll = length(l);
  if (any(isnan(n)) || any(isnan(l)) || isnan(rl) || !(ln > 0.0) || !(ll > 0.0) || isinf(ln) ||
    isinf(ll))
  {
    return 0.0;
  }
  n = n / ln;
  l = l / ll;
  rl = sphericalCapClampLightRadius(rl);
  vec3 t;
  vec3 b;
  vec3 nt;
  vec3 nb;
  visibilityMaskFrame(l, t, b);
  visibilityMaskFrame(n, nt, nb);
  float halfSin = sin(0.5 * rl);
  float capArea = 4.0 * sphericalCapPi * halfSin * halfSin;
  int samples = visibilityMaskLightSamples(rl);
  // The spiral turns by the golden angle a sample, by rotation.
  vec2 turn = visibilityMaskGoldenTurn;
  vec2 spiral = vec2(1.0, 0.0);
  for (int i = 0; i < samples; ++i)
  {
    float down = 2.0 * halfSin * halfSin * (float(i) + 0.5) / float(samples);
    float sinT = sqrt(max(0.0, down * (2.0 - down)));
    vec3 w = (1.0 - down) * l + sinT * (spiral.x * t + spiral.y * b);
    float z = dot(n, w);
    int cell = visibilityMaskCellInFrame(nt, nb, n, w);
    if (z > 0.0 && cell >= 0 && visibilityMaskIsOpen(cell))
    {
      coverage += vec2(1.0, z) * (capArea / float(samples));
    }
    spiral = vec2(spiral.x * turn.x - spiral.y * turn.y, spiral.y * turn.x + spiral.x * turn.y);
  }
  float s = sin(rl);
  return coverage.y / (sphericalCapPi * s * s);
}

// vtkVisibilityMask::SkyTransfer(): the sky through the open cells (their solid angle and
// cosine integral in open, vtkVisibilityMask::OpenSums()) less the lights' coverage.
float visibilityMaskSkyTransfer(vec3 n, vec2 open, vec2 coverage, bool cosineWeighted)
{
  if (any(isnan(n)) || !(length(n) > 0.0) || any(isnan(coverage)))
  {
    return 0.0;
  }
  return cosineWeighted ? max(0.0, open.y - coverage.y) / sphericalCapPi
                        : max(0.0, open.x - coverage.x) / (2.0 * sphericalCapPi);
}
