/*=========================================================================

  Program:   ApertureLighting
  Module:    TestAperturePrecomputeTimeSeries.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// vtkAperturePrecompute on a time series: a ground whose bump moves from step to step (a
// temporal source of this file). Its time steps pass through; a step in which the bump moves
// casts rays only near it (and of the unmoved points' rays, only those that pass near it) and
// gives what a fresh filter gives on that step; a second visit to a step is a lookup of the same
// output; a step with other cells computes everything (and says so), and the same step again
// from a modified source casts nothing; a surface moved as a whole keeps every point's rays when
// they follow point ids, not positions; a moved local origin recasts everything.

#include "vtkAperturePrecompute.h"

#include "vtkApertureTestHarness.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataAlgorithm.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <cmath>
#include <string>

using vtkApertureTest::Check;

namespace
{
// A square ground of side 2 (n x n quads, each two triangles) with a bump of radius 0.25 and
// height 0.2 at x = -0.5 + 0.25 t at time step t (0 .. 3), shifted by Shift along x; with
// another resolution at step 3 when ChangeCells is on. Points outside the bump stay at z = 0.
class vtkMovingBump : public vtkPolyDataAlgorithm
{
public:
  static vtkMovingBump* New();
  vtkTypeMacro(vtkMovingBump, vtkPolyDataAlgorithm);
  vtkSetMacro(Shift, double);
  vtkSetMacro(ChangeCells, bool);

protected:
  vtkMovingBump() { this->SetNumberOfInputPorts(0); }

  int RequestInformation(
    vtkInformation*, vtkInformationVector**, vtkInformationVector* out) override
  {
    const double steps[4] = { 0.0, 1.0, 2.0, 3.0 };
    const double range[2] = { 0.0, 3.0 };
    vtkInformation* info = out->GetInformationObject(0);
    info->Set(vtkStreamingDemandDrivenPipeline::TIME_STEPS(), steps, 4);
    info->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
    return 1;
  }

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* out) override
  {
    vtkInformation* info = out->GetInformationObject(0);
    const double t = info->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP())
      ? info->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP())
      : 0.0;
    const int n = this->ChangeCells && t == 3.0 ? 40 : 64;
    const double centre = -0.5 + 0.25 * t;
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    for (int j = 0; j <= n; ++j)
    {
      for (int i = 0; i <= n; ++i)
      {
        const double x = -1.0 + 2.0 * i / n, y = -1.0 + 2.0 * j / n;
        const double r2 = ((x - centre) * (x - centre) + y * y) / (0.25 * 0.25);
        const double z = r2 < 1.0 ? 0.2 * (1.0 - r2) * (1.0 - r2) : 0.0;
        points->InsertNextPoint(x + this->Shift, y, z);
      }
    }
    vtkNew<vtkCellArray> triangles;
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        const vtkIdType a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
        const vtkIdType lower[3] = { a, b, d }, upper[3] = { a, d, c };
        triangles->InsertNextCell(3, lower);
        triangles->InsertNextCell(3, upper);
      }
    }
    vtkPolyData* output = vtkPolyData::GetData(out);
    output->SetPoints(points);
    output->SetPolys(triangles);
    output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), t);
    return 1;
  }

private:
  double Shift = 0.0;
  bool ChangeCells = false;
};
vtkStandardNewMacro(vtkMovingBump);

vtkDataArray* Radius(vtkAperturePrecompute* filter)
{
  return vtkPolyData::SafeDownCast(filter->GetOutputDataObject(0))
    ->GetPointData()
    ->GetArray("ApertureRadius");
}

// The largest and the mean |difference| of two radius arrays.
void Compare(vtkDataArray* a, vtkDataArray* b, double& largest, double& mean)
{
  largest = 0.0;
  mean = 0.0;
  const vtkIdType n = std::min(a->GetNumberOfTuples(), b->GetNumberOfTuples());
  for (vtkIdType i = 0; i < n; ++i)
  {
    const double d = std::abs(a->GetTuple1(i) - b->GetTuple1(i));
    largest = std::max(largest, d);
    mean += d / n;
  }
}

// A fresh filter's radius at time step t, for comparison.
vtkSmartPointer<vtkDataArray> Cold(vtkMovingBump* source, double t)
{
  vtkNew<vtkAperturePrecompute> cold;
  cold->SetInputConnection(source->GetOutputPort());
  cold->SetNumberOfRays(64);
  cold->LimitDistanceOn();
  cold->SetMaximumDistance(0.3);
  cold->UpdateTimeStep(t);
  return Radius(cold);
}

void TestSteps()
{
  vtkNew<vtkMovingBump> source;
  source->SetChangeCells(true);
  vtkNew<vtkAperturePrecompute> filter;
  filter->SetInputConnection(source->GetOutputPort());
  filter->SetNumberOfRays(64);
  filter->LimitDistanceOn();
  filter->SetMaximumDistance(0.3);
  filter->ReuseUnmovedPointsOn();
  filter->UpdateInformation();
  vtkInformation* outInfo = filter->GetOutputInformation(0);
  Check(outInfo->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS()) == 4,
    "the input's 4 time steps pass through");

  filter->UpdateTimeStep(1.0);
  vtkDataObject* output = filter->GetOutputDataObject(0);
  Check(output->GetInformation()->Get(vtkDataObject::DATA_TIME_STEP()) == 1.0,
    "the output is for the time asked for");
  Check(filter->GetLastUpdate() == vtkAperturePrecompute::COMPUTED, "a first step is computed");
  const vtkIdType all = filter->GetNumberOfSurfacePoints();
  auto first = vtk::TakeSmartPointer(Radius(filter)->NewInstance());
  first->DeepCopy(Radius(filter));

  // The bump moves by 0.25: only points within reach of where it was or is cast rays again.
  filter->UpdateTimeStep(2.0);
  const vtkIdType cast = filter->GetNumberOfSurfacePoints();
  std::cout << "bump moved: " << cast << " of " << all << " points cast rays again, "
            << filter->GetNumberOfReusedPoints() << " reused\n";
  Check(filter->GetLastUpdate() == vtkAperturePrecompute::MOVED_POINTS, "a moved bump: reuse");
  Check(cast > 0 && cast < all / 2, "a moved bump: fewer than half cast rays", cast, all / 2.0);
  Check(cast + filter->GetNumberOfReusedPoints() == all, "every point cast or reused");
  // Points near the bump that stayed where they were cast only their rays that pass near it.
  const vtkIdType traced = filter->GetNumberOfRaysTraced();
  std::cout << "bump moved: " << traced << " of " << cast * 64 << " rays traced\n";
  Check(traced > 0 && traced < cast * 64 * 3 / 4,
    "a moved bump: unmoved points trace only rays near it", traced, cast * 48.0);
  double largest, mean;
  Compare(Radius(filter), Cold(source, 2.0), largest, mean);
  std::cout << "moved step against a fresh filter: largest |d radius| " << largest << ", mean "
            << mean << "\n";
  Check(largest == 0.0, "a moved step gives what a fresh filter gives", largest, 0.0);

  // A second visit is a lookup.
  filter->UpdateTimeStep(1.0);
  Check(filter->GetLastUpdate() == vtkAperturePrecompute::CACHED_TIME_STEP, "a second visit");
  Check(filter->GetNumberOfSurfacePoints() == 0, "a second visit casts no ray");
  Compare(Radius(filter), first, largest, mean);
  Check(largest == 0.0 && Radius(filter)->GetNumberOfTuples() == first->GetNumberOfTuples(),
    "a second visit gives the first visit's output", largest, 0.0);

  // Other cells: everything again, the same as fresh.
  filter->UpdateTimeStep(3.0);
  Check(filter->GetLastUpdate() == vtkAperturePrecompute::NEW_TOPOLOGY, "other cells: said so");
  Check(filter->GetNumberOfReusedPoints() == 0, "other cells: nothing reused");
  Compare(Radius(filter), Cold(source, 3.0), largest, mean);
  Check(largest == 0.0, "other cells give what a fresh filter gives", largest, 0.0);

  // The same step from a modified source: nothing moved, so no ray is cast (nor a BVH built).
  source->Modified();
  filter->UpdateTimeStep(3.0);
  Check(filter->GetLastUpdate() == vtkAperturePrecompute::MOVED_POINTS &&
      filter->GetNumberOfSurfacePoints() == 0 && filter->GetNumberOfRaysTraced() == 0,
    "nothing moved: no ray cast");
  Compare(Radius(filter), Cold(source, 3.0), largest, mean);
  Check(largest == 0.0, "nothing moved: what a fresh filter gives", largest, 0.0);
}

// The whole surface moved by 0.5 along x: with rays by point id every point keeps its caps
// exactly (a translation by a power of two keeps the coordinates relative to the scene's
// middle); by position, points get other rays.
void TestRaysFollowIds()
{
  for (const bool byId : { true, false })
  {
    vtkNew<vtkMovingBump> source;
    vtkNew<vtkAperturePrecompute> filter;
    filter->SetInputConnection(source->GetOutputPort());
    filter->SetNumberOfRays(64);
    filter->SetKeyRaysByPointId(byId);
    filter->ReuseUnmovedPointsOn();
    filter->UpdateTimeStep(0.0);
    auto before = vtk::TakeSmartPointer(Radius(filter)->NewInstance());
    before->DeepCopy(Radius(filter));
    source->SetShift(0.5);
    filter->UpdateTimeStep(0.0);
    double largest, mean;
    Compare(Radius(filter), before, largest, mean);
    std::cout << (byId ? "rays by id" : "rays by position")
              << ", surface moved as a whole: largest |d radius| " << largest << ", mean " << mean
              << "\n";
    Check(filter->GetNumberOfReusedPoints() == 0, "a surface moved as a whole casts again");
    if (byId)
    {
      Check(largest == 0.0, "rays by id: every point keeps its caps", largest, 0.0);
    }
    else
    {
      Check(mean > 1e-4, "rays by position: points get other rays", mean, 1e-4);
    }
  }
}
}

// A point on no cell far off the ground moves: no vertex moved, but the scene's local origin
// (the middle of all points' bounds) did, which rounds every coordinate as a fresh run would:
// every point casts again.
void TestOriginMoved()
{
  vtkNew<vtkMovingBump> source;
  source->UpdateTimeStep(0.0);
  vtkNew<vtkPolyData> surface;
  surface->DeepCopy(source->GetOutput());
  const vtkIdType stray = surface->GetPoints()->InsertNextPoint(5.0, 0.0, 0.0);
  vtkNew<vtkAperturePrecompute> filter;
  filter->SetInputData(surface);
  filter->SetNumberOfRays(64);
  filter->LimitDistanceOn();
  filter->SetMaximumDistance(0.3);
  filter->ReuseUnmovedPointsOn();
  filter->Update();
  surface->GetPoints()->SetPoint(stray, 9.0, 0.0, 0.0);
  surface->GetPoints()->Modified();
  filter->Update();
  Check(filter->GetLastUpdate() == vtkAperturePrecompute::MOVED_POINTS &&
      filter->GetNumberOfReusedPoints() == 0,
    "another local origin: every point casts", filter->GetNumberOfReusedPoints(), 0.0);
  vtkNew<vtkAperturePrecompute> fresh;
  fresh->SetInputData(surface);
  fresh->SetNumberOfRays(64);
  fresh->LimitDistanceOn();
  fresh->SetMaximumDistance(0.3);
  fresh->Update();
  double largest, mean;
  Compare(Radius(filter), Radius(fresh), largest, mean);
  Check(largest == 0.0, "another local origin: what a fresh filter gives", largest, 0.0);
}

int TestAperturePrecomputeTimeSeries(int, char*[])
{
  TestSteps();
  TestRaysFollowIds();
  TestOriginMoved();
  return vtkApertureTest::Result();
}
