/*=========================================================================

  Program:   ApertureLighting
  Module:    TestHorizonLightingGLSL.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Evaluates the GLSL twin of vtkHorizonLighting on the GPU (a full-screen pass writing floats,
// one texel per case) for random horizons, normals and lights of every size, and bad input, and
// compares with the C++ values; the environment sky with a wedge table of a coloured sky.

#include "vtkApertureGLSLEvaluator.h"
#include "vtkApertureSkyTexture.h"
#include "vtkApertureTestEnvironment.h"
#include "vtkApertureTestHarness.h"
#include "vtkEnvironmentMap.h"
#include "vtkHorizonLighting.h"
#include "vtkHorizonLightingCodeGLSL.h"
#include "vtkHorizonLightingGLSL.h"
#include "vtkSphericalCap.h"
#include "vtkSphericalCapGLSL.h"

#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkPointData.h"
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
constexpr int Sectors = 32;
constexpr int Width = 64; // cases per row
constexpr int Azimuths = 256;
constexpr int Elevations = 64;

// A normal (xyz) and light radius (w); a light direction; 32 horizons.
struct Case
{
  float Normal[4];
  float Light[4];
  float Horizons[Sectors];
};

// Pass 0: transfer, coverage (solid angle, cosine), cosine-weighted sky. Pass 1: the open sky,
// a decoded code, the horizon at the light's azimuth, the open share the light leaves. Pass 2: the
// environment sky (RGB), less the light's cosine coverage, and its red less the light's solid
// angle.
const char* EvaluatorFS = R"(//VTK::System::Dec
//VTK::Output::Dec
uniform sampler2D normals;
uniform sampler2D lights;
uniform sampler2D horizonTexels;
uniform int pass;
in vec2 texCoord;
//VTK::HorizonLighting::Dec
void main()
{
  ivec2 texel = ivec2(texCoord * vec2(textureSize(normals, 0)));
  vec4 p = texelFetch(normals, texel, 0);
  vec3 l = texelFetch(lights, texel, 0).xyz;
  for (int j = 0; j < HORIZON_LIGHTING_SECTORS / 4; ++j)
  {
    vec4 four = texelFetch(horizonTexels, ivec2(texel.x * HORIZON_LIGHTING_SECTORS / 4 + j, texel.y), 0);
    horizonLightingHorizons[4 * j] = four.x;
    horizonLightingHorizons[4 * j + 1] = four.y;
    horizonLightingHorizons[4 * j + 2] = four.z;
    horizonLightingHorizons[4 * j + 3] = four.w;
  }
  vec2 coverage;
  float transfer = horizonLightingLightTransfer(p.xyz, l, p.w, coverage);
  if (pass == 0)
  {
    gl_FragData[0] = vec4(transfer, coverage, horizonLightingSkyTransfer(p.xyz, coverage, true));
  }
  else if (pass == 2)
  {
    gl_FragData[0] = vec4(horizonLightingEnvironmentSky(p.xyz, coverage, true),
      horizonLightingEnvironmentSky(p.xyz, coverage, false).r);
  }
  else
  {
    float code = float((texel.x + texel.y * textureSize(normals, 0).x) % 256);
    gl_FragData[0] = vec4(horizonLightingSkyTransfer(p.xyz, coverage, false),
      horizonLightingDecode(code / 255.0), horizonLightingAt(sphericalCapAtan2(l.y, l.x)),
      horizonLightingOpenShare(p.xyz, coverage, true));
  }
}
)";

std::vector<Case> MakeCases()
{
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(5);
  auto next = [&random](double low, double high)
  {
    random->Next();
    return random->GetRangeValue(low, high);
  };
  const double radii[] = { 0.001, 0.0047, 0.064, 0.314, 0.785 };
  std::vector<Case> cases(4096);
  for (size_t i = 0; i < cases.size(); ++i)
  {
    Case& c = cases[i];
    const double level = next(-0.3, 0.6), amplitude = next(0.0, 0.4), phase = next(0.0, 2 * Pi);
    for (int k = 0; k < Sectors; ++k)
    {
      const double h =
        level + amplitude * std::cos(2.0 * Pi * (k + 0.5) / Sectors + phase) + next(-0.05, 0.05);
      c.Horizons[k] = static_cast<float>(std::min(0.5 * Pi, std::max(-0.5 * Pi, h)));
    }
    const double n[3] = { next(-0.6, 0.6), next(-0.6, 0.6), next(0.5, 1.5) };
    const double rl = i % 6 < 5 ? radii[i % 6] : next(1e-4, 0.785);
    const double azimuth = next(0.0, 2.0 * Pi);
    const double base = vtkHorizonLighting::HorizonAt(c.Horizons, Sectors, azimuth);
    const double elevation = i % 2 == 0
      ? std::min(0.5 * Pi, std::max(-0.2, base + next(-1.5, 1.5) * rl))
      : next(-0.1, 0.5 * Pi);
    const double l[3] = { std::cos(elevation) * std::cos(azimuth),
      std::cos(elevation) * std::sin(azimuth), std::sin(elevation) };
    for (int k = 0; k < 3; ++k)
    {
      c.Normal[k] = static_cast<float>(n[k]);
      c.Light[k] = static_cast<float>(2.0 * l[k]);
    }
    c.Normal[3] = static_cast<float>(rl);
    c.Light[3] = 0.0f;
  }
  // Bad input: NaN normal, zero light, NaN radius, an oversized light.
  const float nan = std::numeric_limits<float>::quiet_NaN();
  cases[0].Normal[0] = nan;
  cases[1].Light[0] = cases[1].Light[1] = cases[1].Light[2] = 0.0f;
  cases[2].Normal[3] = nan;
  cases[3].Normal[3] = 50.0f;
  return cases;
}

// A wedge table of a coloured environment (vtkApertureTest::GlowSky()) in the horizons' frame
// (the world's).
std::vector<float> MakeWedgeTable(vtkImageData* table)
{
  vtkNew<vtkEnvironmentMap> environment;
  environment->SetImage(vtkApertureTest::GlowSky());
  const double identity[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  vtkSmartPointer<vtkImageData> wedges;
  wedges.TakeReference(environment->NewWedgeTable(Azimuths, Elevations, identity));
  table->DeepCopy(wedges);
  auto* values = vtkFloatArray::SafeDownCast(table->GetPointData()->GetScalars());
  return std::vector<float>(
    values->GetPointer(0), values->GetPointer(0) + values->GetNumberOfValues());
}

// The C++ values of a case for one pass, in the shader's layout.
void Expected(const Case& c, int index, int pass, const std::vector<float>& wedges, double out[4])
{
  const double n[3] = { c.Normal[0], c.Normal[1], c.Normal[2] };
  const double l[3] = { c.Light[0], c.Light[1], c.Light[2] };
  double coverage = 0.0, cosine = 0.0;
  const double transfer =
    vtkHorizonLighting::LightTransfer(n, c.Horizons, Sectors, l, c.Normal[3], &coverage, &cosine);
  if (pass == 2)
  {
    double solid[3];
    vtkHorizonLighting::EnvironmentSkyTransfer(
      n, c.Horizons, Sectors, wedges.data(), Azimuths, Elevations, coverage, cosine, true, out);
    vtkHorizonLighting::EnvironmentSkyTransfer(
      n, c.Horizons, Sectors, wedges.data(), Azimuths, Elevations, coverage, cosine, false, solid);
    out[3] = solid[0];
    return;
  }
  if (pass == 0)
  {
    out[0] = transfer;
    out[1] = coverage;
    out[2] = cosine;
    out[3] = vtkHorizonLighting::SkyTransfer(n, c.Horizons, Sectors, coverage, cosine, true);
    return;
  }
  out[0] = vtkHorizonLighting::SkyTransfer(n, c.Horizons, Sectors, coverage, cosine, false);
  out[1] = vtkHorizonLighting::DecodeAngle(index % 256);
  out[2] = vtkHorizonLighting::HorizonAt(c.Horizons, Sectors, std::atan2(l[1], l[0]));
  out[3] = vtkHorizonLighting::OpenShare(n, c.Horizons, Sectors, coverage, cosine, true);
}
}

int TestHorizonLightingGLSL(int, char*[])
{
  vtkApertureTest::GLSLEvaluator evaluator;
  vtkOpenGLRenderWindow* win = evaluator.GetWindow();

  const std::vector<Case> cases = MakeCases();
  const int height = static_cast<int>(cases.size()) / Width;
  std::vector<float> normals(4 * cases.size()), lights(4 * cases.size());
  std::vector<float> horizons(Sectors * cases.size());
  for (size_t i = 0; i < cases.size(); ++i)
  {
    std::copy(cases[i].Normal, cases[i].Normal + 4, &normals[4 * i]);
    std::copy(cases[i].Light, cases[i].Light + 4, &lights[4 * i]);
    std::copy(cases[i].Horizons, cases[i].Horizons + Sectors, &horizons[Sectors * i]);
  }
  const vtkSmartPointer<vtkTextureObject> uploaded[3] = { evaluator.Upload(Width, height, normals),
    evaluator.Upload(Width, height, lights),
    evaluator.Upload(Width * Sectors / 4, height, horizons) };
  vtkNew<vtkImageData> wedgeImage;
  const std::vector<float> wedges = MakeWedgeTable(wedgeImage);
  vtkNew<vtkTextureObject> wedgeTexture;
  vtkApertureSkyTexture::Upload(wedgeImage, wedgeTexture, win);
  const std::vector<std::pair<const char*, vtkTextureObject*>> textures = {
    { "normals", uploaded[0] }, { "lights", uploaded[1] }, { "horizonTexels", uploaded[2] },
    { "horizonLightingSkyWedges", wedgeTexture }
  };

  std::string fs = EvaluatorFS;
  vtkShaderProgram::Substitute(fs, "//VTK::HorizonLighting::Dec",
    "#define HORIZON_LIGHTING_SECTORS " + std::to_string(Sectors) +
      "\n#define HORIZON_LIGHTING_ENVIRONMENT\n" + vtkSphericalCap::GetGLSLConstants() +
      vtkSphericalCapGLSL + vtkHorizonLighting::GetGLSLConstants() + vtkHorizonLightingCodeGLSL +
      vtkHorizonLightingGLSL);
  vtkOpenGLQuadHelper quad(win, nullptr, fs.c_str(), "");
  if (!quad.Program || !quad.Program->GetCompiled())
  {
    std::cerr << "The GLSL twin does not compile\n";
    return EXIT_FAILURE;
  }
  const char* names[3][4] = { { "LightTransfer", "coverage", "cosine coverage",
                                "SkyTransfer cosine-weighted" },
    { "SkyTransfer", "DecodeAngle", "HorizonAt", "OpenShare" },
    { "EnvironmentSkyTransfer red", "green", "blue", "red by solid angle" } };
  for (int pass = 0; pass < 3; ++pass)
  {
    const std::vector<float> result = evaluator.Run(quad, Width, height, textures,
      [pass](vtkShaderProgram* program) { program->SetUniformi("pass", pass); });
    double worst[4] = { 0, 0, 0, 0 };
    for (size_t i = 0; i < cases.size(); ++i)
    {
      double want[4];
      Expected(cases[i], static_cast<int>(i), pass, wedges, want);
      // Transfers and skies (1 = a full light or sky) within 2e-3, half an 8-bit level: float
      // and double may take the closed form and the quadrature on either side of the edge;
      // coverages within 2e-3 of the light's own; angles within 1e-5.
      const double cap = vtkSphericalCap::SolidAngleFromCapRadius(vtkSphericalCap::ClampLightRadius(
        std::isnan(cases[i].Normal[3]) ? 0.0 : cases[i].Normal[3]));
      // The environment within 2e-3 of its value or of 1: the texture's filter (GPUs keep 8 bits of
      // its weights) against the C++'s double bilinear, and the skies' closed forms as above.
      const double tolerance[3][4] = { { 2e-3, 2e-3 * cap, 2e-3 * cap, 2e-3 },
        { 2e-3, 1e-5, 1e-5, 2e-3 }, { 2e-3, 2e-3, 2e-3, 2e-3 } };
      for (int k = 0; k < 4; ++k)
      {
        const double got = result[4 * i + k];
        const double error = std::abs(got - want[k]) / (pass == 2 ? std::max(1.0, want[k]) : 1.0);
        vtkApertureTest::Check(std::isfinite(got) && error <= tolerance[pass][k],
          std::string(names[pass][k]) + " of case " + std::to_string(i), got, want[k]);
        worst[k] = std::max(worst[k], std::isfinite(error) ? error : 0.0);
      }
    }
    for (int k = 0; k < 4; ++k)
    {
      if (names[pass][k][0])
      {
        std::cout << names[pass][k] << ": max |GLSL - C++| = " << worst[k] << "\n";
      }
    }
  }
  std::cout << cases.size() << " cases evaluated on " << glGetString(GL_RENDERER) << "\n";
  return vtkApertureTest::Result();
}
