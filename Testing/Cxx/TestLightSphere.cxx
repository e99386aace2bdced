/*=========================================================================

  Program:   ApertureLighting
  Module:    TestLightSphere.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// vtkLightSphere: the direction counts, each level a prefix of the next, a Delaunay
// triangulation, Voronoi weights that sum to 4π and match a Monte-Carlo count of nearest
// directions, and integrals over the sphere that the weights get right where equal weights do
// not.

#include "vtkApertureTestHarness.h"
#include "vtkLightSphere.h"

#include "vtkDoubleArray.h"
#include "vtkMath.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace
{
using vtkApertureTest::Check;

struct Sphere
{
  std::vector<double> Directions, Weights;
};

Sphere Load(int level)
{
  vtkNew<vtkLightSphere> sphere;
  sphere->SetLevel(level);
  Sphere s;
  for (int j = 0; j < sphere->GetNumberOfDirections(); ++j)
  {
    double d[3];
    sphere->GetDirection(j, d);
    s.Directions.insert(s.Directions.end(), d, d + 3);
    s.Weights.push_back(sphere->GetWeight(j));
  }
  return s;
}

int Nearest(const Sphere& s, const double u[3])
{
  int best = 0;
  double bestDot = -2.0;
  for (size_t j = 0; j < s.Weights.size(); ++j)
  {
    const double dot = vtkMath::Dot(u, &s.Directions[3 * j]);
    if (dot > bestDot)
    {
      bestDot = dot;
      best = static_cast<int>(j);
    }
  }
  return best;
}
}

int TestLightSphere(int, char*[])
{
  const double pi = vtkMath::Pi();
  Sphere previous;
  for (int level = 0; level <= vtkLightSphere::MaximumLevel; ++level)
  {
    const Sphere s = Load(level);
    const int k = static_cast<int>(s.Weights.size());
    Check(k == 4 * (1 << (2 * level)) + 2 && k == vtkLightSphere::GetNumberOfDirections(level),
      "k = 4 4^level + 2 at level " + std::to_string(level));
    double sum = 0.0, smallest = 1e9, largest = 0.0, worstNorm = 0.0;
    for (int j = 0; j < k; ++j)
    {
      sum += s.Weights[j];
      smallest = std::min(smallest, s.Weights[j]);
      largest = std::max(largest, s.Weights[j]);
      worstNorm = std::max(worstNorm, std::abs(vtkMath::Norm(&s.Directions[3 * j]) - 1.0));
    }
    const bool prefix = level == 0 ||
      std::equal(previous.Directions.begin(), previous.Directions.end(), s.Directions.begin());
    std::cout << "level " << level << ": k = " << k << ", sum of weights - 4 pi = " << sum - 4 * pi
              << ", largest / smallest cell = " << largest / smallest
              << (level > 0 ? (prefix ? ", extends the level below" : ", NOT A PREFIX") : "")
              << "\n";
    Check(std::abs(sum - 4.0 * pi) < 1e-11, "weights sum to 4 pi");
    Check(worstNorm < 1e-15, "unit directions");
    Check(prefix, "each level extends the one below");
    previous = s;
  }

  // The weights are the Voronoi cells' solid angles (the circumcentre construction needs a
  // Delaunay triangulation): each equals the Monte-Carlo share of directions nearest to it.
  const Sphere s3 = Load(3);
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(7);
  const int samples = 2000000;
  std::vector<int> counts(s3.Weights.size(), 0);
  for (int i = 0; i < samples; ++i)
  {
    const double z = 2.0 * random->GetNextValue() - 1.0;
    const double phi = 2.0 * pi * random->GetNextValue();
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double u[3] = { r * std::cos(phi), r * std::sin(phi), z };
    ++counts[Nearest(s3, u)];
  }
  double worstZ = 0.0;
  for (size_t j = 0; j < counts.size(); ++j)
  {
    const double p = s3.Weights[j] / (4.0 * pi);
    const double sigma = std::sqrt(p * (1.0 - p) / samples);
    worstZ = std::max(worstZ, std::abs(double(counts[j]) / samples - p) / sigma);
  }
  std::cout << "level 3 weights vs the share of " << samples
            << " random directions nearest to each: worst deviation " << worstZ << " sigma\n";
  Check(worstZ < 5.0, "weights are the Voronoi cells' solid angles");

  // Integrals over the sphere: the clamped cosine (pi) and the squared cosine (4 pi / 3), for
  // random normals, with these weights and with equal weights 4 pi / k.
  for (int level = 2; level <= 4; ++level)
  {
    const Sphere s = Load(level);
    const double equal = 4.0 * pi / s.Weights.size();
    double worstVoronoi = 0.0, worstEqual = 0.0, worstSquare = 0.0;
    for (int trial = 0; trial < 200; ++trial)
    {
      double n[3] = { random->GetNextValue() - 0.5, random->GetNextValue() - 0.5,
        random->GetNextValue() - 0.5 };
      vtkMath::Normalize(n);
      double voronoi = 0.0, uniform = 0.0, square = 0.0;
      for (size_t j = 0; j < s.Weights.size(); ++j)
      {
        const double c = vtkMath::Dot(n, &s.Directions[3 * j]);
        voronoi += s.Weights[j] * std::max(c, 0.0);
        uniform += equal * std::max(c, 0.0);
        square += s.Weights[j] * c * c;
      }
      worstVoronoi = std::max(worstVoronoi, std::abs(voronoi - pi) / pi);
      worstEqual = std::max(worstEqual, std::abs(uniform - pi) / pi);
      worstSquare = std::max(worstSquare, std::abs(square - 4.0 * pi / 3.0) / (4.0 * pi / 3.0));
    }
    std::cout << "level " << level << ": integral of max(n.l, 0), worst relative error "
              << worstVoronoi << " with the weights, " << worstEqual
              << " with equal weights; of (n.l)^2: " << worstSquare << "\n";
    Check(worstVoronoi < worstEqual, "the weights integrate better than equal weights");
    Check(worstSquare < 0.01, "the weights integrate (n.l)^2 within 1%");
  }

  // Arrays, clamping and out-of-range queries.
  vtkNew<vtkLightSphere> sphere;
  sphere->SetLevel(99);
  Check(sphere->GetLevel() == vtkLightSphere::MaximumLevel, "level clamped to the maximum");
  sphere->SetLevel(-3);
  Check(sphere->GetLevel() == 0, "level clamped to 0");
  sphere->SetLevel(4);
  vtkSmartPointer<vtkDoubleArray> directions;
  directions.TakeReference(sphere->NewDirections());
  vtkSmartPointer<vtkDoubleArray> weights;
  weights.TakeReference(sphere->NewWeights());
  Check(directions->GetNumberOfTuples() == 1026 && directions->GetNumberOfComponents() == 3 &&
      weights->GetNumberOfTuples() == 1026 &&
      std::string(directions->GetName()) == "LightDirections",
    "arrays of the level's directions and weights");
  double d[3];
  Check(!sphere->GetDirection(1026, d) && !sphere->GetDirection(-1, d) &&
      sphere->GetWeight(1026) == 0.0,
    "out-of-range directions are refused");
  return vtkApertureTest::Result();
}
