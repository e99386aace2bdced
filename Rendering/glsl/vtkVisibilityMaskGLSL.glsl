// ApertureLighting: the GLSL twin of vtkVisibilityMask (see that class for the cells and the
// formulas). Needs vtkSphericalCapGLSL (for its pi and atan2), vtkVisibilityMask's
// GetGLSLConstants(), VISIBILITY_MASK_SIDE (the grid's side; side² cells) and the mask being
// shaded in visibilityMaskWords (cell k at bit k % 32 of word k / 32) with the cells' cosine
// integrals in visibilityMaskCellCosines (vtkVisibilityMask::CellCosine()).

const int visibilityMaskCells = VISIBILITY_MASK_SIDE * VISIBILITY_MASK_SIDE;
uint visibilityMaskWords[(visibilityMaskCells + 31) / 32];
uniform float visibilityMaskCellCosines[visibilityMaskCells];

// Duff et al.'s tangent frame of a unit normal.
void visibilityMaskFrame(vec3 n, out vec3 t, out vec3 b)
{
  float sign = n.z >= 0.0 ? 1.0 : -1.0;
  float a = -1.0 / (sign + n.z);
  float c = n.x * n.y * a;
  t = vec3(1.0 + sign * n.x * n.x * a, sign * c, -sign * n.x);
  b = vec3(c, sign + n.y * n.y * a, -n.y);
}

// The concentric map from the unit disk back to the square [-1, 1]^2.
vec2 visibilityMaskDiskToSquare(vec2 p)
{
  float quarter = 0.25 * sphericalCapPi;
  float r = length(p);
  float phi = sphericalCapAtan2(p.y, p.x);
  phi = phi < -quarter ? phi + 2.0 * sphericalCapPi : phi;
  if (phi < quarter)
  {
    return vec2(r, r * phi / quarter);
  }
  if (phi < 3.0 * quarter)
  {
    return vec2(r * (2.0 * quarter - phi) / quarter, r);
  }
  if (phi < 5.0 * quarter)
  {
    return vec2(-r, -r * (phi - sphericalCapPi) / quarter);
  }
  return vec2(-r * (6.0 * quarter - phi) / quarter, -r);
}

// The cell of unit direction w in the frame (t, b, n), or -1 below its plane.
int visibilityMaskCellInFrame(vec3 t, vec3 b, vec3 n, vec3 w)
{
  float z = dot(w, n);
  if (!(z >= 0.0))
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
  float golden = sphericalCapPi * (3.0 - sqrt(5.0));
  for (int i = 0; i < visibilityMaskLightSamples; ++i)
  {
    float down = 2.0 * halfSin * halfSin * (float(i) + 0.5) / float(visibilityMaskLightSamples);
    float sinT = sqrt(max(0.0, down * (2.0 - down)));
    float angle = golden * float(i);
    vec3 w = (1.0 - down) * l + sinT * (cos(angle) * t + sin(angle) * b);
    float z = dot(n, w);
    int cell = visibilityMaskCellInFrame(nt, nb, n, w);
    if (z > 0.0 && cell >= 0 && visibilityMaskIsOpen(cell))
    {
      coverage += vec2(1.0, z) * (capArea / float(visibilityMaskLightSamples));
    }
  }
  float s = sin(rl);
  return coverage.y / (sphericalCapPi * s * s);
}

// vtkVisibilityMask::SkyTransfer(): the sky through the open cells less the lights' coverage.
float visibilityMaskSkyTransfer(vec3 n, vec2 coverage, bool cosineWeighted)
{
  if (any(isnan(n)) || !(length(n) > 0.0) || any(isnan(coverage)))
  {
    return 0.0;
  }
  float open = 0.0;
  float openCosine = 0.0;
  for (int cell = 0; cell < visibilityMaskCells; ++cell)
  {
    if (visibilityMaskIsOpen(cell))
    {
      open += 2.0 * sphericalCapPi / float(visibilityMaskCells);
      openCosine += visibilityMaskCellCosines[cell];
    }
  }
  return cosineWeighted ? max(0.0, openCosine - coverage.y) / sphericalCapPi
                        : max(0.0, open - coverage.x) / (2.0 * sphericalCapPi);
}
