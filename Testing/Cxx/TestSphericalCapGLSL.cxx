/*=========================================================================

  Program:   ApertureLighting
  Module:    TestSphericalCapGLSL.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Evaluates the GLSL twin of vtkSphericalCap on the GPU (a full-screen pass writing floats, one
// texel per input) over a grid of inputs, random shading configurations and bad inputs, and
// compares with the C++ values.

#include "vtkApertureTestHarness.h"
#include "vtkSphericalCap.h"
#include "vtkSphericalCapGLSL.h"

#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace
{
constexpr double Pi = vtkMath::Pi();
using vtkApertureTest::Check;

// Cap functions read (R1, R2, D, A1, A2); shading functions read normal A1, aperture (A2, R1) and
// light (A3, R2).
struct Case
{
  float R1, R2, D;
  float A1[3], A2[3], A3[3];
};

// The harness's Check with the case's radii and distance and both values in its message.
void Check(bool ok, const char* what, const Case& c, double got, double want)
{
  if (!ok)
  {
    std::ostringstream message;
    message << what << " r1=" << c.R1 << " r2=" << c.R2 << " d=" << c.D << ": GLSL " << got
            << ", C++ " << want;
    vtkApertureTest::Check(ok, message.str());
  }
}

// Each pass writes one vec4 per input texel.
const char* EvaluatorFS = R"(//VTK::System::Dec
//VTK::Output::Dec
uniform sampler2D params;
uniform sampler2D axes1;
uniform sampler2D axes2;
uniform sampler2D axes3;
uniform int pass;
in vec2 texCoord;
//VTK::SphericalCap::Dec
void main()
{
  ivec2 texel = ivec2(texCoord * vec2(textureSize(params, 0)));
  vec4 p = texelFetch(params, texel, 0);
  vec3 a1 = texelFetch(axes1, texel, 0).xyz;
  vec3 a2 = texelFetch(axes2, texel, 0).xyz;
  vec3 a3 = texelFetch(axes3, texel, 0).xyz;
  float c0, c1, c2, c3, c4;
  float t0 = sphericalCapLightTransfer(sphericalCapExact, sphericalCapCentroid, a1, a2, p.x, a3, p.y, c0);
  float t1 = sphericalCapLightTransfer(sphericalCapExact, sphericalCapMoment, a1, a2, p.x, a3, p.y, c1);
  float t2 = sphericalCapLightTransfer(sphericalCapSmoothstep, sphericalCapCentroid, a1, a2, p.x, a3, p.y, c2);
  float t3 = sphericalCapLightTransfer(sphericalCapSimplified, sphericalCapCentroid, a1, a2, p.x, a3, p.y, c3);
  float t4 = sphericalCapLightTransfer(sphericalCapBentNormal, sphericalCapCentroid, a1, a2, p.x, a3, p.y, c4);
  if (pass == 3)
  {
    gl_FragData[0] = vec4(t0, t1, t2, t3);
  }
  else if (pass == 4)
  {
    gl_FragData[0] = vec4(t4, c0, c2, c3);
  }
  else if (pass == 5)
  {
    gl_FragData[0] = vec4(c4, sphericalCapSkyTransfer(p.x, c0, dot(a1, a2), true),
      sphericalCapSkyTransfer(p.x, c0, dot(a1, a2), false), 0.0);
  }
  else if (pass == 0)
  {
    gl_FragData[0] = vec4(sphericalCapIntersectionArea(p.x, p.y, p.z),
      sphericalCapIntersectionAreaSmoothstep(p.x, p.y, p.z),
      sphericalCapSimplifiedShadowFactor(p.x, p.y, p.z),
      sphericalCapSphereLightIrradiance(p.x, p.z));
  }
  else if (pass == 1)
  {
    gl_FragData[0] = vec4(sphericalCapIntersectionMoment(a1, p.x, a2, p.y),
      sphericalCapSolidAngle(p.x));
  }
  else
  {
    gl_FragData[0] = vec4(sphericalCapIntersectionCentroid(a1, p.x, a2, p.y),
      sphericalCapRadiusFromSolidAngle(p.z));
  }
}
)";

std::vector<Case> MakeCases()
{
  std::vector<Case> cases;
  std::vector<double> radii = { 1e-3, 4.7e-3, 0.01, 0.064, 0.314, 0.785, 0.5 * Pi, 2.0, 3.0 };
  for (int i = 1; i <= 12; ++i)
  {
    radii.push_back(0.5 * Pi * i / 13.0);
  }
  for (double r1 : radii)
  {
    for (double r2 : radii)
    {
      std::vector<double> ds;
      for (int i = 0; i <= 40; ++i)
      {
        ds.push_back(Pi * i / 40.0);
      }
      for (double edge : { r1 + r2, std::abs(r1 - r2) })
      {
        for (double eps : { -1e-3, -1e-5, 1e-5, 1e-3 })
        {
          if (edge + eps >= 0.0 && edge + eps <= Pi)
          {
            ds.push_back(edge + eps);
          }
        }
      }
      for (double d : ds)
      {
        Case c;
        c.R1 = static_cast<float>(r1);
        c.R2 = static_cast<float>(r2);
        c.D = static_cast<float>(d);
        // Axes at distance d, in a tilted plane, not unit length.
        const double u[3] = { 0.0, 0.6, 0.8 };
        const double v[3] = { 1.0, 0.0, 0.0 };
        for (int k = 0; k < 3; ++k)
        {
          c.A1[k] = static_cast<float>(2.0 * u[k]);
          c.A2[k] = static_cast<float>(0.5 * (std::cos(d) * u[k] + std::sin(d) * v[k]));
          c.A3[k] = static_cast<float>(std::cos(0.5 * d) * u[k] - std::sin(0.5 * d) * v[k]);
        }
        cases.push_back(c);
      }
    }
  }
  // Shading configurations: a normal, a bent normal within 80 degrees of it, a light anywhere
  // in the upper half, aperture radii in [0, pi/2] and light radii from the sun to 0.785.
  vtkMath::RandomSeed(11);
  const double lightRadii[] = { 1e-4, 4.7e-3, 0.064, 0.314, 0.785 };
  for (int i = 0; i < 5000; ++i)
  {
    double n[3] = { vtkMath::Gaussian(), vtkMath::Gaussian(), vtkMath::Gaussian() };
    vtkMath::Normalize(n);
    double t[3], b[3];
    vtkMath::Perpendiculars(n, t, b, vtkMath::Random(0.0, 2.0 * Pi));
    const double tilt = vtkMath::Random(0.0, 1.4);
    const double lightAngle = vtkMath::Random(0.0, 0.5 * Pi + 0.3);
    const double turn = vtkMath::Random(0.0, 2.0 * Pi);
    Case c;
    c.R1 = static_cast<float>(vtkMath::Random(0.0, 0.5 * Pi));
    c.R2 = static_cast<float>(i % 6 < 5 ? lightRadii[i % 6] : vtkMath::Random(1e-4, 0.785));
    c.D = 0.0f;
    for (int k = 0; k < 3; ++k)
    {
      c.A1[k] = static_cast<float>(n[k]);
      c.A2[k] = static_cast<float>(std::cos(tilt) * n[k] + std::sin(tilt) * t[k]);
      c.A3[k] = static_cast<float>(std::cos(lightAngle) * n[k] +
        std::sin(lightAngle) * (std::cos(turn) * t[k] + std::sin(turn) * b[k]));
    }
    cases.push_back(c);
  }

  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const Case bad[] = {
    { nan, 0.5f, 0.3f, { 0, 0, 1 }, { 0, 1, 0 }, { 0, 0, 1 } },
    { 0.5f, nan, 0.3f, { 0, 0, 1 }, { 0, 1, 0 }, { 0, 0, 1 } },
    { 0.5f, 0.5f, nan, { 0, 0, 1 }, { 0, 1, 0 }, { 0, 0, 1 } },
    { -0.5f, 0.5f, 0.3f, { 0, 0, 1 }, { 0, 0.3f, 1 }, { 0, 0, 1 } },
    { 0.5f, 0.5f, -1.0f, { 0, 0, 0 }, { 0, 0, 1 }, { 0, 0, 1 } },
    { inf, 0.5f, 7.0f, { nan, 0, 1 }, { 0, 0, 1 }, { 0, 0, 1 } },
    { 0.5f, -inf, -inf, { inf, 0, 1 }, { 0, 0, 1 }, { 0, 0, 0 } },
    { 0.7f, 0.7f, 0.0f, { 0, 0, 1 }, { 0, 0, 1 }, { nan, 0, 1 } },
  };
  cases.insert(cases.end(), std::begin(bad), std::end(bad));
  return cases;
}

// The C++ values for one pass, in the same layout as the shader's output.
void Expected(const Case& c, int pass, double out[4])
{
  const double a1[3] = { c.A1[0], c.A1[1], c.A1[2] };
  const double a2[3] = { c.A2[0], c.A2[1], c.A2[2] };
  if (pass == 0)
  {
    out[0] = vtkSphericalCap::IntersectionArea(c.R1, c.R2, c.D);
    out[1] = vtkSphericalCap::IntersectionAreaSmoothstep(c.R1, c.R2, c.D);
    out[2] = vtkSphericalCap::SimplifiedShadowFactor(c.R1, c.R2, c.D);
    out[3] = vtkSphericalCap::SphereLightIrradiance(c.R1, c.D);
  }
  else if (pass == 1)
  {
    vtkSphericalCap::IntersectionMoment(a1, c.R1, a2, c.R2, out);
    out[3] = vtkSphericalCap::SolidAngleFromCapRadius(c.R1);
  }
  else if (pass == 2)
  {
    vtkSphericalCap::IntersectionCentroid(a1, c.R1, a2, c.R2, out);
    out[3] = vtkSphericalCap::CapRadiusFromSolidAngle(c.D);
  }
  else
  {
    // Shading: normal a1, aperture (a2, R1), light (a3, R2).
    const double a3[3] = { c.A3[0], c.A3[1], c.A3[2] };
    double t[5], coverage[5];
    const int modes[5][2] = { { vtkSphericalCap::EXACT, vtkSphericalCap::CENTROID },
      { vtkSphericalCap::EXACT, vtkSphericalCap::MOMENT },
      { vtkSphericalCap::SMOOTHSTEP, vtkSphericalCap::CENTROID },
      { vtkSphericalCap::SIMPLIFIED, vtkSphericalCap::CENTROID },
      { vtkSphericalCap::BENT_NORMAL, vtkSphericalCap::CENTROID } };
    for (int k = 0; k < 5; ++k)
    {
      t[k] = vtkSphericalCap::LightTransfer(modes[k][0], modes[k][1], a1, a2, c.R1, a3, c.R2);
      coverage[k] = vtkSphericalCap::LightCoverage(modes[k][0], a2, c.R1, a3, c.R2);
    }
    const double cosNB = static_cast<double>(c.A1[0]) * c.A2[0] +
      static_cast<double>(c.A1[1]) * c.A2[1] + static_cast<double>(c.A1[2]) * c.A2[2];
    const double pass3[4] = { t[0], t[1], t[2], t[3] };
    const double pass4[4] = { t[4], coverage[0], coverage[2], coverage[3] };
    const double pass5[4] = { coverage[4],
      vtkSphericalCap::SkyTransfer(c.R1, coverage[0], cosNB, true),
      vtkSphericalCap::SkyTransfer(c.R1, coverage[0], cosNB, false), 0.0 };
    const double* chosen = pass == 3 ? pass3 : (pass == 4 ? pass4 : pass5);
    std::copy(chosen, chosen + 4, out);
  }
}

vtkSmartPointer<vtkTextureObject> Upload(
  vtkOpenGLRenderWindow* win, int width, int height, std::vector<float>& data)
{
  auto tex = vtkSmartPointer<vtkTextureObject>::New();
  tex->SetContext(win);
  tex->Create2DFromRaw(width, height, 4, VTK_FLOAT, data.data());
  return tex;
}
}

int TestSphericalCapGLSL(int, char*[])
{
  vtkNew<vtkRenderWindow> renWin;
  renWin->SetOffScreenRendering(1);
  renWin->SetSize(16, 16);
  vtkNew<vtkRenderer> renderer;
  renWin->AddRenderer(renderer);
  renWin->Render();
  auto* win = vtkOpenGLRenderWindow::SafeDownCast(renWin);
  if (!win)
  {
    std::cerr << "Not an OpenGL render window\n";
    return EXIT_FAILURE;
  }
  win->MakeCurrent();

  const std::vector<Case> cases = MakeCases();
  const int width = 256;
  const int height = static_cast<int>((cases.size() + width - 1) / width);
  std::vector<float> params(4 * width * height, 0.0f), axes1(params), axes2(params), axes3(params);
  for (size_t i = 0; i < cases.size(); ++i)
  {
    const Case& c = cases[i];
    params[4 * i] = c.R1;
    params[4 * i + 1] = c.R2;
    params[4 * i + 2] = c.D;
    std::copy(c.A1, c.A1 + 3, &axes1[4 * i]);
    std::copy(c.A2, c.A2 + 3, &axes2[4 * i]);
    std::copy(c.A3, c.A3 + 3, &axes3[4 * i]);
  }
  auto paramsTex = Upload(win, width, height, params);
  auto axes1Tex = Upload(win, width, height, axes1);
  auto axes2Tex = Upload(win, width, height, axes2);
  auto axes3Tex = Upload(win, width, height, axes3);

  std::string fs = EvaluatorFS;
  vtkShaderProgram::Substitute(
    fs, "//VTK::SphericalCap::Dec", vtkSphericalCap::GetGLSLConstants() + vtkSphericalCapGLSL);
  vtkOpenGLQuadHelper quad(win, nullptr, fs.c_str(), "");
  if (!quad.Program || !quad.Program->GetCompiled())
  {
    std::cerr << "The GLSL twin does not compile\n";
    return EXIT_FAILURE;
  }

  vtkNew<vtkTextureObject> target;
  target->SetContext(win);
  target->Create2D(width, height, 4, VTK_FLOAT, false);
  vtkNew<vtkOpenGLFramebufferObject> fbo;
  fbo->SetContext(win);
  vtkOpenGLState* state = win->GetState();
  state->PushFramebufferBindings();
  fbo->Bind();
  fbo->AddColorAttachment(0, target);
  fbo->ActivateDrawBuffer(0);
  fbo->ActivateReadBuffer(0);
  if (!fbo->StartNonOrtho(width, height))
  {
    std::cerr << "Cannot render to a float framebuffer\n";
    return EXIT_FAILURE;
  }
  state->vtkglViewport(0, 0, width, height);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDisable(GL_BLEND);
  state->vtkglDisable(GL_SCISSOR_TEST);

  const char* names[6][4] = { { "IntersectionArea", "IntersectionAreaSmoothstep",
                                "SimplifiedShadowFactor", "SphereLightIrradiance" },
    { "IntersectionMoment.x", "IntersectionMoment.y", "IntersectionMoment.z",
      "SolidAngleFromCapRadius" },
    { "IntersectionCentroid.x", "IntersectionCentroid.y", "IntersectionCentroid.z",
      "CapRadiusFromSolidAngle" },
    { "LightTransfer EXACT CENTROID", "LightTransfer EXACT MOMENT", "LightTransfer SMOOTHSTEP",
      "LightTransfer SIMPLIFIED" },
    { "LightTransfer BENT_NORMAL", "LightCoverage EXACT", "LightCoverage SMOOTHSTEP",
      "LightCoverage SIMPLIFIED" },
    { "LightCoverage BENT_NORMAL", "SkyTransfer cosine-weighted", "SkyTransfer", "(unused)" } };
  // Solid angles within 1e-4 sr, the moment within 1e-4 per component, the sphere light within
  // 1e-3 of pi sin^2(sigma), factors and angles within 1e-4, the centroid within 2e-3 where it is
  // well defined (a lens of at least 1% of the smaller cap; the worst cases are caps wider than a
  // hemisphere, which shading does not use).
  // Transfers (1 = a full VTK light) within 1e-3, a quarter of an 8-bit level.
  const double tolerance[6][4] = { { 1e-4, 1e-4, 1e-4, 1e-4 }, { 1e-4, 1e-4, 1e-4, 1e-4 },
    { 2e-3, 2e-3, 2e-3, 1e-4 }, { 1e-3, 1e-3, 1e-3, 1e-3 }, { 1e-3, 1e-4, 1e-4, 1e-4 },
    { 1e-4, 1e-4, 1e-4, 1e-4 } };

  std::vector<float> result(4 * width * height);
  for (int pass = 0; pass < 6; ++pass)
  {
    win->GetShaderCache()->ReadyShaderProgram(quad.Program);
    paramsTex->Activate();
    axes1Tex->Activate();
    axes2Tex->Activate();
    axes3Tex->Activate();
    quad.Program->SetUniformi("params", paramsTex->GetTextureUnit());
    quad.Program->SetUniformi("axes3", axes3Tex->GetTextureUnit());
    quad.Program->SetUniformi("axes1", axes1Tex->GetTextureUnit());
    quad.Program->SetUniformi("axes2", axes2Tex->GetTextureUnit());
    quad.Program->SetUniformi("pass", pass);
    quad.Render();
    glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, result.data());
    paramsTex->Deactivate();
    axes1Tex->Deactivate();
    axes2Tex->Deactivate();
    axes3Tex->Deactivate();

    double worst[4] = { 0, 0, 0, 0 };
    double worstRelativeArea = 0.0;
    for (size_t i = 0; i < cases.size(); ++i)
    {
      double want[4];
      Expected(cases[i], pass, want);
      for (int k = 0; k < 4; ++k)
      {
        const Case& c = cases[i];
        const double got = result[4 * i + k];
        const double err = std::abs(got - want[k]);
        double tol = tolerance[pass][k];
        if (pass == 0 && k == 3)
        {
          // Relative to the light's full irradiance pi sin^2(sigma), as for the C++ accuracy test.
          tol = 1e-3 * Pi * std::pow(std::sin(std::min<double>(std::max(0.0f, c.R1), 0.5 * Pi)), 2);
        }
        if (pass == 2 && k < 3 &&
          vtkSphericalCap::IntersectionArea(c.R1, c.R2, c.D) <
            0.01 * vtkSphericalCap::SolidAngleFromCapRadius(std::min(c.R1, c.R2)))
        {
          tol = 2.0; // Direction not defined to float precision; only finiteness is checked.
        }
        Check(std::isfinite(got) && err <= tol, names[pass][k], c, got, want[k]);
        if (std::isfinite(got) && tol < 2.0)
        {
          worst[k] = std::max(worst[k], err);
        }
      }
      if (pass == 0 && std::isfinite(cases[i].R1) && cases[i].R1 > 0 && cases[i].R2 > 0)
      {
        const double small = vtkSphericalCap::SolidAngleFromCapRadius(
          std::min<double>(std::min(cases[i].R1, cases[i].R2), Pi));
        worstRelativeArea = std::max(worstRelativeArea, std::abs(result[4 * i] - want[0]) / small);
      }
    }
    for (int k = 0; k < 4; ++k)
    {
      if (names[pass][k][0] != '(')
      {
        std::cout << names[pass][k] << ": max |GLSL - C++| = " << worst[k] << "\n";
      }
    }
    if (pass == 0)
    {
      std::cout << "IntersectionArea: max |GLSL - C++| relative to the smaller cap = "
                << worstRelativeArea << "\n";
      Check(worstRelativeArea <= 1e-3,
        "single-precision area loses its relative accuracy for small caps");
    }
  }
  state->PopFramebufferBindings();
  std::cout << cases.size() << " inputs evaluated on " << glGetString(GL_RENDERER) << "\n";
  return vtkApertureTest::Result();
}
