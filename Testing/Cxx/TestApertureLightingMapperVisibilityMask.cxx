/*=========================================================================

  Program:   ApertureLighting
  Module:    TestApertureLightingMapperVisibilityMask.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// The Visibility mask mode of vtkApertureLightingMapper, pixel by pixel: camera-facing squares
// of two triangles, each square with its own normal and mask (a wall on one side, scattered
// holes), lit by suns of several sizes, by a sphere light and by the sky, uniform or from an HDR
// environment through the open cells. The masks are
// evaluated per vertex and the results interpolated, so every tested pixel must match
// vtkVisibilityMask at the triangle's vertices, interpolated, within 1/255: 256-bit masks through
// vtkApertureLightingMapper, 64-bit and 256-bit blocks through
// vtkCompositeApertureLightingMapper, 1024-bit masks resampled to 256 bits. Data without masks,
// with bad ones, without normals or drawn flat warn once and get the exact cap.

#include "vtkApertureLightingMapper.h"
#include "vtkApertureTestEnvironment.h"
#include "vtkApertureTestHarness.h"
#include "vtkCompositeApertureLightingMapper.h"
#include "vtkEnvironmentMap.h"
#include "vtkSphericalCap.h"
#include "vtkVisibilityMask.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkMath.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTestErrorObserver.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>

namespace
{
using vtkApertureTest::Check;

constexpr double Pi = vtkMath::Pi();
constexpr int Grid = 8;           // squares per side
constexpr int Size = 32;          // pixels per square side
constexpr int Side = Grid * Size; // the window's, in pixels

struct Square
{
  double Normal[3];
  std::vector<unsigned char> Mask;
};

// A mask of `bits` cells around n: closed behind a wall facing `wall` (cells whose centre
// direction leans toward it past `height`), with one cell in seven flipped; with `blocks`, the
// cells of each 2 x 2 block of the grid alike (so that halving the side loses nothing).
std::vector<unsigned char> MakeMask(
  const double n[3], int bits, const double wall[3], double height, bool blocks)
{
  const int side = vtkVisibilityMask::GetSide(bits);
  std::vector<unsigned char> mask(bits / 8, 0);
  for (int cell = 0; cell < bits; ++cell)
  {
    int i = cell % side, j = cell / side;
    if (blocks)
    {
      i -= i % 2;
      j -= j % 2;
    }
    double w[3];
    vtkVisibilityMask::Direction(n, (i + 0.5) / side, (j + 0.5) / side, w);
    const bool flipped = (i * 5 + j * 3) % 7 == 0;
    const bool open = (vtkMath::Dot(w, wall) < height) != flipped;
    mask[cell / 8] |= static_cast<unsigned char>(open ? 1 << (cell % 8) : 0);
  }
  return mask;
}

// The squares with their masks on a grid of `bits` cells whose side is twice or half theirs:
// the same open region (cell i, j takes cell i side / newSide, j side / newSide).
std::vector<Square> Regrid(std::vector<Square> squares, int bits)
{
  const int to = vtkVisibilityMask::GetSide(bits);
  for (Square& q : squares)
  {
    const int from = vtkVisibilityMask::GetSide(8 * static_cast<int>(q.Mask.size()));
    std::vector<unsigned char> mask(bits / 8, 0);
    for (int cell = 0; cell < bits; ++cell)
    {
      const int source = (cell % to) * from / to + from * ((cell / to) * from / to);
      const int open = (q.Mask[source / 8] >> (source % 8)) & 1;
      mask[cell / 8] |= static_cast<unsigned char>(open << (cell % 8));
    }
    q.Mask = mask;
  }
  return squares;
}

std::vector<Square> MakeSquares(int bits, bool blocks)
{
  vtkMath::RandomSeed(11);
  std::vector<Square> squares(Grid * Grid);
  for (Square& q : squares)
  {
    const double tilt = vtkMath::Random(0.0, 0.6), turn = vtkMath::Random(0.0, 2.0 * Pi);
    q.Normal[0] = std::sin(tilt) * std::cos(turn);
    q.Normal[1] = std::sin(tilt) * std::sin(turn);
    q.Normal[2] = std::cos(tilt);
    const double azimuth = vtkMath::Random(0.0, 2.0 * Pi);
    const double wall[3] = { std::cos(azimuth), std::sin(azimuth), 0.0 };
    q.Mask = MakeMask(q.Normal, bits, wall, vtkMath::Random(0.1, 0.6), blocks);
  }
  return squares;
}

// Grid x Grid squares filling the window, each of two triangles whose points carry the square's
// normal and mask, and a cap (bent normal = normal, radius 1) for the arrays every aperture
// needs.
vtkSmartPointer<vtkPolyData> MakeMesh(const std::vector<Square>& squares)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> cells;
  vtkNew<vtkFloatArray> normals, bent, radius;
  vtkNew<vtkUnsignedCharArray> masks;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  bent->SetName("BentNormal");
  bent->SetNumberOfComponents(3);
  radius->SetName("ApertureRadius");
  masks->SetName("VisibilityMask");
  masks->SetNumberOfComponents(static_cast<int>(squares[0].Mask.size()));
  for (int j = 0; j < Grid; ++j)
  {
    for (int i = 0; i < Grid; ++i)
    {
      const Square& q = squares[i + Grid * j];
      const double x0 = -0.5 * Side + Size * i, y0 = -0.5 * Side + Size * j;
      const vtkIdType first = points->GetNumberOfPoints();
      const double corners[4][2] = { { x0, y0 }, { x0 + Size, y0 }, { x0 + Size, y0 + Size },
        { x0, y0 + Size } };
      for (const auto& c : corners)
      {
        points->InsertNextPoint(c[0], c[1], 0.0);
        normals->InsertNextTuple(q.Normal);
        bent->InsertNextTuple(q.Normal);
        radius->InsertNextValue(1.0);
        std::vector<double> bytes(q.Mask.begin(), q.Mask.end());
        masks->InsertNextTuple(bytes.data());
      }
      const vtkIdType lower[3] = { first, first + 1, first + 2 };
      const vtkIdType upper[3] = { first, first + 2, first + 3 };
      cells->InsertNextCell(3, lower);
      cells->InsertNextCell(3, upper);
    }
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(cells);
  mesh->GetPointData()->SetNormals(normals);
  mesh->GetPointData()->AddArray(bent);
  mesh->GetPointData()->AddArray(radius);
  mesh->GetPointData()->AddArray(masks);
  return mesh;
}

struct Scene
{
  double Light[3]; // toward a directional light, or a sphere light's centre
  double Radius;   // angular (directional) or world (positional)
  bool Positional;
  double Sky;
  bool Environment = false; // the sky from SkyModel's environment, else uniform
};

// An environment whose red channel (the one the pixels are read from) is brightest low in the
// north-east (vtkApertureTest::GlowSky()), and what the mapper makes of it for 256-bit masks: its
// mean radiance over a cell's cap, and the model's frame (the world's here) to its own.
struct SkyModel
{
  SkyModel()
  {
    this->Environment->SetImage(vtkApertureTest::GlowSky());
    this->Environment->SetAzimuth(40.0);
    this->Environment->GetWorldToEnvironment(this->ToEnvironment);
    vtkSmartPointer<vtkImageData> table;
    table.TakeReference(
      this->Environment->NewMeanRadianceTable(64, 32, vtkVisibilityMask::CellCapRadius(256)));
    auto* values = vtkFloatArray::SafeDownCast(table->GetPointData()->GetScalars());
    this->Table.assign(values->GetPointer(0), values->GetPointer(0) + values->GetNumberOfValues());
  }

  vtkNew<vtkEnvironmentMap> Environment;
  double ToEnvironment[9];
  std::vector<float> Table;
};

// The expected 0..1 value at a vertex at p of a square with this normal and mask, or of the
// exact cap where `cap` is set (a flat square's cap, with `facet`).
enum Expect
{
  Mask,
  Cap,
  FacetCap
};

double AtVertex(const Scene& s, const Square& q, const double p[3], double intensity, Expect expect,
  const SkyModel& model)
{
  double l[3] = { s.Light[0], s.Light[1], s.Light[2] };
  double rl = s.Radius;
  if (s.Positional)
  {
    vtkMath::Subtract(s.Light, p, l);
    rl = vtkSphericalCap::SphereLightCapRadius(s.Radius, vtkMath::Norm(l));
  }
  const double* n = q.Normal;
  if (expect != Mask)
  {
    // Without the point normals the fragment's normal is its facet's, the view's +z.
    const double facet[3] = { 0.0, 0.0, 1.0 };
    const double* normal = expect == FacetCap ? facet : n;
    const double t = vtkSphericalCap::LightTransfer(
      vtkSphericalCap::EXACT, vtkSphericalCap::CENTROID, normal, n, 1.0, l, rl);
    const double covered = vtkSphericalCap::LightCoverage(vtkSphericalCap::EXACT, n, 1.0, l, rl);
    return intensity * t +
      s.Sky * vtkSphericalCap::SkyTransfer(1.0, covered, vtkMath::Dot(normal, n), true);
  }
  const int bits = 8 * static_cast<int>(q.Mask.size());
  double coverage, cosine;
  const double t =
    vtkVisibilityMask::LightTransfer(n, q.Mask.data(), bits, l, rl, &coverage, &cosine);
  double sky[3] = { vtkVisibilityMask::SkyTransfer(
    n, q.Mask.data(), bits, coverage, cosine, true) };
  if (s.Environment)
  {
    vtkVisibilityMask::EnvironmentSkyTransfer(n, q.Mask.data(), bits, model.Table.data(), 64, 32,
      model.ToEnvironment, coverage, cosine, true, sky);
  }
  return intensity * t + s.Sky * sky[0];
}

class Bench
{
public:
  Bench()
  {
    this->Mapper->ScalarVisibilityOff();
    this->Mapper->SetShadingModeToVisibilityMask();
    this->Actor->SetMapper(this->Mapper);
    this->Actor->GetProperty()->SetAmbient(0.0);
    this->Actor->GetProperty()->SetDiffuse(1.0);
    this->Actor->GetProperty()->SetSpecular(0.0);
    this->Renderer->AddActor(this->Actor);
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->ParallelProjectionOn();
    camera->SetParallelScale(0.5 * Side);
    camera->SetPosition(0, 0, 1000);
    camera->SetFocalPoint(0, 0, 0);
    camera->SetViewUp(0, 1, 0);
    camera->SetClippingRange(500, 1500);
    this->Light->SetLightTypeToSceneLight();
    this->Light->SetIntensity(this->Intensity);
    this->Light->SetConeAngle(180.0);
    this->Renderer->AddLight(this->Light);
    this->Window->SetSize(Side, Side);
    this->Window->SetMultiSamples(0);
    this->Window->AddRenderer(this->Renderer);
    this->Mapper->GetApertureLighting()->AddObserver(vtkCommand::WarningEvent, this->Observer);
  }

  // Renders a scene and returns the largest difference (/255) from the expected pixels: the
  // values at the vertices of the pixel's triangle, interpolated.
  double Run(const Scene& s, const std::vector<Square>& squares, Expect expect)
  {
    this->Light->SetPositional(s.Positional);
    this->Light->SetPosition(s.Light);
    this->Light->SetFocalPoint(0, 0, 0);
    vtkApertureLightingMapper::SetLightRadius(this->Light, s.Radius);
    this->Window->Render();
    vtkNew<vtkUnsignedCharArray> pixels;
    this->Window->GetPixelData(0, 0, Side - 1, Side - 1, 1, pixels, 0);
    double worst = 0.0;
    for (int j = 0; j < Grid; ++j)
    {
      for (int i = 0; i < Grid; ++i)
      {
        const Square& q = squares[i + Grid * j];
        const double x0 = -0.5 * Side + Size * i, y0 = -0.5 * Side + Size * j;
        double corner[4];
        const double offsets[4][2] = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } };
        for (int c = 0; c < 4; ++c)
        {
          const double p[3] = { x0 + Size * offsets[c][0], y0 + Size * offsets[c][1], 0.0 };
          corner[c] = AtVertex(s, q, p, this->Intensity, expect, this->Sky);
        }
        for (int py = Size * j + 2; py < Size * (j + 1) - 2; py += 3)
        {
          for (int px = Size * i + 2; px < Size * (i + 1) - 2; px += 3)
          {
            // Barycentric in the lower (0, 1, 2) or upper (0, 2, 3) triangle.
            const double u = (px + 0.5 - Size * i) / Size, v = (py + 0.5 - Size * j) / Size;
            const double value = u >= v
              ? (1.0 - u) * corner[0] + (u - v) * corner[1] + v * corner[2]
              : (1.0 - v) * corner[0] + u * corner[2] + (v - u) * corner[3];
            const double want = 255.0 * std::min(1.0, value);
            worst = std::max(worst, std::abs(pixels->GetValue(3 * (px + Side * py)) - want));
          }
        }
      }
    }
    return worst;
  }

  const double Intensity = 0.8;
  SkyModel Sky;
  vtkNew<vtkApertureLightingMapper> Mapper;
  vtkNew<vtkActor> Actor;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkLight> Light;
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkTest::ErrorObserver> Observer;
};

std::vector<Scene> Scenes()
{
  // Suns low and high, small and wide, a sphere light, and the sky.
  std::vector<Scene> scenes;
  for (double radius : { 0.0047, 0.064, 0.4 })
  {
    scenes.push_back({ { 0.98, 0.1, 0.3 }, radius, false, 0.0 });
    scenes.push_back({ { -0.5, 0.8, 0.45 }, radius, false, 0.3 });
  }
  scenes.push_back({ { 0.2, 0.3, 0.9 }, 0.1, false, 0.3 });
  scenes.push_back({ { 80.0, -60.0, 60.0 }, 30.0, true, 0.2 });
  scenes.push_back({ { -0.5, 0.8, 0.45 }, 0.064, false, 0.4, true });
  scenes.push_back({ { 80.0, -60.0, 60.0 }, 30.0, true, 0.3, true });
  return scenes;
}

void RunScenes(Bench& bench, const std::vector<Square>& squares, const std::string& what)
{
  for (const Scene& s : Scenes())
  {
    bench.Mapper->SetSkyIntensity(s.Sky);
    bench.Mapper->SetSkyEnvironment(s.Environment ? bench.Sky.Environment.Get() : nullptr);
    const double worst = bench.Run(s, squares, Mask);
    std::cout << what << ", " << (s.Positional ? "sphere light R=" : "sun r=") << s.Radius
              << ", sky " << s.Sky << (s.Environment ? " (environment)" : "")
              << ": max |GPU - CPU| = " << worst << "/255\n";
    // 0.5 for the 8-bit rounding, 0.5 for single precision and interpolation.
    Check(worst <= 1.0, what + ": mask pixels differ from vtkVisibilityMask (/255)", worst, 1.0);
  }
}

// Expects one warning naming `clue` and the exact cap.
void ExpectExactCap(
  Bench& bench, const std::vector<Square>& squares, const std::string& clue, Expect expect = Cap)
{
  const Scene s = Scenes()[1];
  bench.Mapper->SetSkyIntensity(s.Sky);
  bench.Mapper->SetSkyEnvironment(nullptr);
  const double worst = bench.Run(s, squares, expect);
  Check(worst <= 1.0, clue + ": the exact cap (/255)", worst, 1.0);
  Check(bench.Observer->GetWarningMessage().find(clue) != std::string::npos, clue + ": warns");
  bench.Observer->Clear();
  bench.Run(s, squares, expect);
  Check(!bench.Observer->GetWarning(), clue + ": a persisting problem warns once");
}

void TestPerVertex(Bench& bench)
{
  const std::vector<Square> squares = MakeSquares(256, false);
  auto mesh = MakeMesh(squares);
  bench.Mapper->SetInputData(mesh);
  RunScenes(bench, squares, "256 bits");
  Check(!bench.Observer->GetWarning(), "good masks shade without a warning");

  // Data with horizons too: after a frame in Horizon mode, whose packed attributes have the
  // masks' names, the masks are packed again.
  vtkNew<vtkFloatArray> horizons;
  horizons->SetName("HorizonAngles");
  horizons->SetNumberOfComponents(32);
  horizons->SetNumberOfTuples(mesh->GetNumberOfPoints());
  horizons->Fill(0.2);
  mesh->GetPointData()->AddArray(horizons);
  bench.Mapper->SetShadingModeToHorizon();
  bench.Window->Render();
  bench.Mapper->SetShadingModeToVisibilityMask();
  RunScenes(bench, squares, "256 bits after Horizon");

  // Finer masks go to the GPU as 256 bits; made of 2 x 2 blocks, they lose nothing: they shade
  // as the 256-bit masks of their blocks (the same open region, and the samples of 256 cells).
  const std::vector<Square> fine = MakeSquares(1024, true);
  bench.Mapper->SetInputData(MakeMesh(fine));
  RunScenes(bench, Regrid(fine, 256), "1024 bits as 256");
  bench.Mapper->SetInputData(mesh);

  // Bad masks, none, no normals, flat shading: one warning each, and the exact cap.
  vtkNew<vtkUnsignedCharArray> five;
  five->SetName("VisibilityMask");
  five->SetNumberOfComponents(5);
  five->SetNumberOfTuples(mesh->GetNumberOfPoints());
  five->Fill(255);
  mesh->GetPointData()->AddArray(five);
  ExpectExactCap(bench, squares, "40 bits");
  vtkNew<vtkFloatArray> floats;
  floats->SetName("VisibilityMask");
  floats->SetNumberOfComponents(32);
  floats->SetNumberOfTuples(mesh->GetNumberOfPoints());
  floats->Fill(255);
  mesh->GetPointData()->AddArray(floats);
  ExpectExactCap(bench, squares, "not an unsigned char array");
  mesh->GetPointData()->RemoveArray("VisibilityMask");
  ExpectExactCap(bench, squares, "ComputeVisibilityMask");

  auto masked = MakeMesh(squares);
  bench.Mapper->SetInputData(masked);
  bench.Actor->GetProperty()->SetInterpolationToFlat();
  ExpectExactCap(bench, squares, "flat interpolation", FacetCap);
  bench.Actor->GetProperty()->SetInterpolationToGouraud();
  masked->GetPointData()->SetNormals(nullptr);
  ExpectExactCap(bench, squares, "point normals", FacetCap);
}

// Squares in two blocks through the composite mapper, one block's masks of 64 bits (which the
// other's 256 bits make 256 bits too, the same region), the other's of 256.
void TestComposite(Bench& bench)
{
  const std::vector<Square> fine = MakeSquares(256, false);
  const std::vector<Square> coarse = MakeSquares(64, false);
  auto low = MakeMesh(coarse);
  auto high = MakeMesh(fine);
  std::vector<Square> squares = fine;
  const std::vector<Square> upsampled = Regrid(coarse, 256);
  std::copy(upsampled.begin(), upsampled.begin() + Grid * Grid / 2, squares.begin());
  for (vtkPolyData* half : { low.Get(), high.Get() })
  {
    vtkNew<vtkCellArray> cells;
    const vtkIdType first = half == low ? 0 : Grid * Grid / 2;
    const vtkIdType last = half == low ? Grid * Grid / 2 : Grid * Grid;
    for (vtkIdType c = first; c < last; ++c)
    {
      const vtkIdType lower[3] = { 4 * c, 4 * c + 1, 4 * c + 2 };
      const vtkIdType upper[3] = { 4 * c, 4 * c + 2, 4 * c + 3 };
      cells->InsertNextCell(3, lower);
      cells->InsertNextCell(3, upper);
    }
    half->SetPolys(cells);
  }
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetBlock(0, low);
  blocks->SetBlock(1, high);
  vtkNew<vtkCompositeApertureLightingMapper> composite;
  composite->SetInputDataObject(blocks);
  composite->ScalarVisibilityOff();
  composite->GetApertureLighting()->SetShadingModeToVisibilityMask();
  vtkNew<vtkTest::ErrorObserver> observer;
  composite->GetApertureLighting()->AddObserver(vtkCommand::WarningEvent, observer);
  bench.Actor->SetMapper(composite);
  for (const Scene& s : Scenes())
  {
    // The 64-bit blocks shade as 256 bits on the GPU, whose cells' middles and caps are not
    // those of the 64 cells: the environment sky is checked on the mapper's own masks above.
    if (s.Environment)
    {
      continue;
    }
    composite->GetApertureLighting()->SetSkyIntensity(s.Sky);
    const double worst = bench.Run(s, squares, Mask);
    std::cout << "composite, 64 and 256 bits: max |GPU - CPU| = " << worst << "/255\n";
    Check(worst <= 1.0, "mask pixels of the composite mapper differ (/255)", worst, 1.0);
  }
  Check(!observer->GetWarning(), "the composite mapper shades without a warning");
  bench.Actor->SetMapper(bench.Mapper);
}
}

int TestApertureLightingMapperVisibilityMask(int, char*[])
{
  Bench bench;
  TestPerVertex(bench);
  TestComposite(bench);
  return vtkApertureTest::Result();
}
