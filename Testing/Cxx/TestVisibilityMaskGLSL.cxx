/*=========================================================================

  Program:   ApertureLighting
  Module:    TestVisibilityMaskGLSL.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Evaluates the GLSL twin of vtkVisibilityMask on the GPU (a full-screen pass writing floats,
// one texel per case) for random normals, lights of every size and wall-like 256-cell masks, and
// bad input, and compares with the C++ values.

#include "vtkApertureGLSLEvaluator.h"
#include "vtkApertureTestHarness.h"
#include "vtkSphericalCap.h"
#include "vtkSphericalCapGLSL.h"
#include "vtkVisibilityMask.h"
#include "vtkVisibilityMaskGLSL.h"

#include "vtkMath.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkShaderProgram.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

namespace
{
constexpr double Pi = vtkMath::Pi();
constexpr int Side = 16, Cells = Side * Side;
constexpr int Width = 64; // cases per row

// A normal (xyz) and light radius (w); a light direction; the mask's cells.
struct Case
{
  float Normal[4];
  float Light[4];
  unsigned char Mask[Cells / 8];
};

// The mask reaches the shader as 16-bit halves of its 32-bit words, exact in floats.
const char* EvaluatorFS = R"(//VTK::System::Dec
//VTK::Output::Dec
uniform sampler2D normals;
uniform sampler2D lights;
uniform sampler2D maskTexels;
uniform sampler2D openSums;
uniform int pass;
in vec2 texCoord;
//VTK::VisibilityMask::Dec
void main()
{
  ivec2 texel = ivec2(texCoord * vec2(textureSize(normals, 0)));
  vec4 p = texelFetch(normals, texel, 0);
  vec3 l = texelFetch(lights, texel, 0).xyz;
  for (int j = 0; j < visibilityMaskCells / 64; ++j)
  {
    vec4 halves = texelFetch(maskTexels, ivec2(texel.x * visibilityMaskCells / 64 + j, texel.y), 0);
    visibilityMaskWords[2 * j] = uint(halves.x) | (uint(halves.y) << 16u);
    visibilityMaskWords[2 * j + 1] = uint(halves.z) | (uint(halves.w) << 16u);
  }
  vec2 coverage;
  float transfer = visibilityMaskLightTransfer(p.xyz, l, p.w, coverage);
  vec2 open = texelFetch(openSums, texel, 0).xy;
  if (pass == 0)
  {
    gl_FragData[0] =
      vec4(transfer, coverage, visibilityMaskSkyTransfer(p.xyz, open, coverage, true));
  }
  else
  {
    vec3 n = normalize(p.xyz);
    vec3 w = normalize(l);
    gl_FragData[0] = vec4(visibilityMaskSkyTransfer(p.xyz, open, coverage, false),
      float(visibilityMaskCellOf(n, w)), 0.0, 0.0);
  }
}
)";

std::vector<Case> MakeCases()
{
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(9);
  auto next = [&random](double low, double high)
  {
    random->Next();
    return random->GetRangeValue(low, high);
  };
  const double radii[] = { 0.001, 0.0047, 0.064, 0.314, 0.785 };
  std::vector<Case> cases(2048);
  for (size_t i = 0; i < cases.size(); ++i)
  {
    Case& c = cases[i];
    double n[3] = { next(-1, 1), next(-1, 1), next(-1, 1) }, l[3];
    vtkMath::Normalize(n);
    const double tilt = next(0.0, 1.7), turn = next(0.0, 2.0 * Pi);
    double t[3], b[3];
    vtkVisibilityMask::Frame(n, t, b);
    for (int k = 0; k < 3; ++k)
    {
      l[k] =
        std::cos(tilt) * n[k] + std::sin(tilt) * (std::cos(turn) * t[k] + std::sin(turn) * b[k]);
    }
    // Open above a tilted elevation in the frame, as a wall leaves it.
    const double level = next(-0.2, 0.7), phase = next(0.0, 2.0 * Pi);
    std::fill_n(c.Mask, Cells / 8, 0);
    for (int cell = 0; cell < Cells; ++cell)
    {
      double w[3];
      vtkVisibilityMask::Direction(n, (cell % Side + 0.5) / Side, (cell / Side + 0.5) / Side, w);
      const double azimuth = std::atan2(vtkMath::Dot(w, b), vtkMath::Dot(w, t));
      c.Mask[cell / 8] |=
        vtkMath::Dot(w, n) > level + 0.4 * std::cos(azimuth - phase) ? 1 << (cell % 8) : 0;
    }
    for (int k = 0; k < 3; ++k)
    {
      c.Normal[k] = static_cast<float>(n[k]);
      c.Light[k] = static_cast<float>(l[k]);
    }
    c.Normal[3] = static_cast<float>(i % 6 < 5 ? radii[i % 6] : next(1e-4, 0.785));
    c.Light[3] = 0.0f;
  }
  const float nan = std::numeric_limits<float>::quiet_NaN();
  cases[0].Normal[0] = nan;
  cases[1].Light[0] = cases[1].Light[1] = cases[1].Light[2] = 0.0f;
  cases[2].Normal[3] = nan;
  cases[3].Normal[3] = 50.0f;
  return cases;
}

// The C++ values of a case for one pass, in the shader's layout.
void Expected(const Case& c, int pass, double out[4])
{
  const double n[3] = { c.Normal[0], c.Normal[1], c.Normal[2] };
  const double l[3] = { c.Light[0], c.Light[1], c.Light[2] };
  double coverage = 0.0, cosine = 0.0;
  const double transfer =
    vtkVisibilityMask::LightTransfer(n, c.Mask, Cells, l, c.Normal[3], &coverage, &cosine);
  if (pass == 0)
  {
    out[0] = transfer;
    out[1] = coverage;
    out[2] = cosine;
    out[3] = vtkVisibilityMask::SkyTransfer(n, c.Mask, Cells, coverage, cosine, true);
    return;
  }
  double un[3] = { n[0], n[1], n[2] }, ul[3] = { l[0], l[1], l[2] };
  out[0] = vtkVisibilityMask::SkyTransfer(n, c.Mask, Cells, coverage, cosine, false);
  out[1] = vtkMath::Normalize(un) > 0.0 && vtkMath::Normalize(ul) > 0.0
    ? vtkVisibilityMask::CellOf(un, ul, Side)
    : -1.0;
  out[2] = out[3] = 0.0;
}
}

int TestVisibilityMaskGLSL(int, char*[])
{
  vtkApertureTest::GLSLEvaluator evaluator;
  vtkOpenGLRenderWindow* win = evaluator.GetWindow();

  const std::vector<Case> cases = MakeCases();
  const int height = static_cast<int>(cases.size()) / Width;
  std::vector<float> normals(4 * cases.size()), lights(4 * cases.size()), sums(4 * cases.size());
  std::vector<float> masks(Cells / 16 * cases.size());
  for (size_t i = 0; i < cases.size(); ++i)
  {
    std::copy(cases[i].Normal, cases[i].Normal + 4, &normals[4 * i]);
    std::copy(cases[i].Light, cases[i].Light + 4, &lights[4 * i]);
    double open[2];
    vtkVisibilityMask::OpenSums(cases[i].Mask, Cells, open);
    std::copy(open, open + 2, &sums[4 * i]);
    for (int h = 0; h < Cells / 16; ++h)
    {
      masks[Cells / 16 * i + h] =
        static_cast<float>(cases[i].Mask[2 * h] | (cases[i].Mask[2 * h + 1] << 8));
    }
  }
  const vtkSmartPointer<vtkTextureObject> uploaded[4] = { evaluator.Upload(Width, height, normals),
    evaluator.Upload(Width, height, lights), evaluator.Upload(Width * Cells / 64, height, masks),
    evaluator.Upload(Width, height, sums) };
  const std::vector<std::pair<const char*, vtkTextureObject*>> textures = { { "normals",
                                                                              uploaded[0] },
    { "lights", uploaded[1] }, { "maskTexels", uploaded[2] }, { "openSums", uploaded[3] } };

  std::string fs = EvaluatorFS;
  vtkShaderProgram::Substitute(fs, "//VTK::VisibilityMask::Dec",
    "#define VISIBILITY_MASK_SIDE " + std::to_string(Side) + "\n" +
      vtkSphericalCap::GetGLSLConstants() + vtkSphericalCapGLSL +
      vtkVisibilityMask::GetGLSLConstants() + vtkVisibilityMaskGLSL);
  vtkOpenGLQuadHelper quad(win, nullptr, fs.c_str(), "");
  if (!quad.Program || !quad.Program->GetCompiled())
  {
    std::cerr << "The GLSL twin does not compile\n";
    return EXIT_FAILURE;
  }
  const char* names[2][2] = { { "LightTransfer", "coverage" }, { "SkyTransfer", "CellOf" } };
  int cellsDiffer = 0;
  for (int pass = 0; pass < 2; ++pass)
  {
    const std::vector<float> result = evaluator.Run(quad, Width, height, textures,
      [pass](vtkShaderProgram* program) { program->SetUniformi("pass", pass); });
    double worst[4] = { 0, 0, 0, 0 };
    for (size_t i = 0; i < cases.size(); ++i)
    {
      double want[4];
      Expected(cases[i], pass, want);
      const double cap = vtkSphericalCap::SolidAngleFromCapRadius(vtkSphericalCap::ClampLightRadius(
        std::isnan(cases[i].Normal[3]) ? 0.0 : cases[i].Normal[3]));
      // A sample on a cell's edge may fall either way in single precision: one sample's share
      // of the light.
      const double share = 1.0 /
        vtkVisibilityMask::LightSamples(
          vtkSphericalCap::ClampLightRadius(
            std::isnan(cases[i].Normal[3]) ? 0.0 : cases[i].Normal[3]),
          Cells);
      const double tolerance[2][4] = {
        { share + 1e-3, cap * share + 1e-7, cap * share + 1e-7, 1e-3 }, { 1e-3, 0.5, 1.0, 1.0 }
      };
      for (int k = 0; k < (pass == 0 ? 4 : 1); ++k)
      {
        const double got = result[4 * i + k], error = std::abs(got - want[k]);
        vtkApertureTest::Check(std::isfinite(got) && error <= tolerance[pass][k],
          std::string(names[pass][k == 0 ? 0 : 1]) + " " + std::to_string(k) + " of case " +
            std::to_string(i),
          got, want[k]);
        worst[k] = std::max(worst[k], std::isfinite(error) ? error : 0.0);
      }
      cellsDiffer += pass == 1 && result[4 * i + 1] != static_cast<float>(want[1]);
    }
    std::cout << names[pass][0] << ": max |GLSL - C++| = " << worst[0] << "\n";
    if (pass == 0)
    {
      std::cout << "coverage: " << worst[1] << " sr, cosine coverage " << worst[2]
                << ", cosine-weighted sky " << worst[3] << "\n";
    }
  }
  std::cout << "CellOf differs in " << cellsDiffer << " of " << cases.size() << " cases\n";
  vtkApertureTest::Check(cellsDiffer <= static_cast<int>(cases.size()) / 200,
    "cells agree but on their edges", cellsDiffer, static_cast<int>(cases.size()) / 200);
  return vtkApertureTest::Result();
}
