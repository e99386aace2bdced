/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkAperturePrecompute.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkAperturePrecompute.h"

#include "vtkApertureCellCheck.h"
#include "vtkApertureDistributedOccluders.h"
#include "vtkApertureHistory.h"
#include "vtkApertureRayPacket.h"
#include "vtkApertureRaySampler.h"
#include "vtkApertureRayScene.h"
#include "vtkApertureRefinement.h"
#include "vtkApertureSceneSurfaces.h"
#include "vtkApertureSurface.h"
#include "vtkApertureSurfaceOutput.h"
#include "vtkApertureText.h"
#include "vtkHorizonHeightField.h"
#include "vtkMortonOrder.h"
#include "vtkSphericalCap.h"
#include "vtkVisibilityMask.h"

#include "vtkAlgorithmOutput.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataSetAttributes.h"
#include "vtkDemandDrivenPipeline.h"
#include "vtkExtentTranslator.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <atomic>
#include <bitset>
#include <cfloat>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkAperturePrecompute);

namespace
{
constexpr double Pi = vtkMath::Pi();
constexpr int Lanes = vtkApertureRayPacket::Lanes;

using Caps = vtkApertureHistory::Caps;

// What the mask asks for: its grid's side (0 for no mask) and rays per cell along a side.
struct MaskSettings
{
  int Side = 0;
  int RaysSide = 1;
};

// A retraced point with more moved boxes than this within its reach casts every ray.
constexpr int MaximumBoxes = 8;

// Casts the rays of a range of the `needed` receiving points of one surface (all when empty:
// otherwise vtkApertureHistory's plans, with `history` for the points to RETRACE), in Morton
// order, writes their caps, and counts the rays it traced into `traced`.
class CastRays
{
public:
  CastRays(const vtkApertureSurface& surface, const vtkApertureRayScene& scene,
    const vtkApertureRaySampler& sampler, float maximumDistance, const MaskSettings& mask,
    const std::vector<unsigned char>& needed, const vtkApertureHistory* history, Caps& caps,
    std::atomic<vtkIdType>& traced)
    : Surface(surface)
    , Scene(scene)
    , Sampler(sampler)
    , MaximumDistance(maximumDistance)
    , Mask(mask)
    , Needed(needed)
    , History(history)
    , Out(caps)
    , Traced(traced)
  {
    std::vector<float> positions(3 * surface.GetNumberOfPoints());
    for (vtkIdType i = 0; i < surface.GetNumberOfPoints(); ++i)
    {
      std::copy_n(surface.GetPosition(i), 3, &positions[3 * i]);
    }
    this->Order = vtkMortonOrder::Order(positions.data(), surface.GetNumberOfPoints());
    if (!needed.empty())
    {
      this->Order.erase(std::remove_if(this->Order.begin(), this->Order.end(),
                          [&needed](std::uint32_t id) { return !needed[id]; }),
        this->Order.end());
    }
  }

  vtkIdType GetNumberOfPoints() const { return static_cast<vtkIdType>(this->Order.size()); }

  void operator()(vtkIdType begin, vtkIdType end) const
  {
    vtkApertureRayPacket packet(this->Scene, this->Surface);
    std::vector<int> seen(this->Mask.Side * this->Mask.Side);
    std::vector<float> directions;
    vtkIdType traced = 0;
    for (vtkIdType k = begin; k < end; ++k)
    {
      const vtkIdType id = this->Order[k];
      if (this->Surface.Valid[id])
      {
        traced += this->Cast(packet, id);
        if (this->Mask.Side > 0)
        {
          traced += this->CastMask(packet, id, seen, directions);
        }
      }
      else
      {
        // Closed, around +z.
        std::fill_n(&this->Out.BentNormal[3 * id], 3, 0.0f);
        this->Out.BentNormal[3 * id + 2] = 1.0f;
        this->Out.Radius[id] = 0.0f;
      }
    }
    this->Traced += traced;
  }

private:
  // The lanes (bits) whose rays pass through none of the `moved` boxes, cleared.
  static unsigned int Keep(vtkApertureRayPacket& packet, int count, const float* boxes, int moved)
  {
    unsigned int kept = 0;
    for (int lane = 0; lane < count; ++lane)
    {
      if (!packet.Crosses(lane, boxes, moved))
      {
        packet.Clear(lane);
        kept |= 1u << lane;
      }
    }
    return kept;
  }

  // The point's caps from its rays; returns how many it traced. A point to RETRACE takes the
  // last answer of each ray that passes through no moved box (lanes cleared before the trace).
  vtkIdType Cast(vtkApertureRayPacket& packet, vtkIdType id) const
  {
    const float* nrm = this->Surface.GetNormal(id);
    vtkApertureRaySampler::Point point;
    this->Sampler.Begin(nrm, this->Surface.Key[id], point);
    const int n = this->Sampler.GetNumberOfRays();
    float boxes[6 * MaximumBoxes];
    int moved = -1;
    if (!this->Needed.empty() && this->Needed[id] == vtkApertureHistory::RETRACE)
    {
      moved = this->History->GetMovedBoxes(&this->Surface.Start[3 * id], boxes, MaximumBoxes);
    }
    const std::uint64_t* last = moved >= 0 ? this->History->GetRays(id) : nullptr;
    std::uint64_t* answers =
      this->Out.Rays.empty() ? nullptr : &this->Out.Rays[size_t(id) * this->Out.RayWords];
    vtkIdType traced = 0;
    int visible = 0;
    double sum[3] = { 0.0, 0.0, 0.0 };
    double cosSum = 0.0;
    for (int first = 0; first < n; first += Lanes)
    {
      const int count = std::min(Lanes, n - first);
      this->Sampler.Directions(
        point, first, count, packet.DirectionsX(), packet.DirectionsY(), packet.DirectionsZ());
      packet.SetFan(id, count, this->MaximumDistance);
      const unsigned int kept = last ? Keep(packet, count, boxes, moved) : 0u;
      const int casting = count - static_cast<int>(std::bitset<Lanes>(kept).count());
      if (casting > 0)
      {
        packet.Trace();
        traced += casting;
      }
      for (int lane = 0; lane < count; ++lane)
      {
        const int ray = first + lane;
        const bool escaped =
          kept >> lane & 1u ? (last[ray / 64] >> (ray % 64) & 1u) != 0 : packet.Visible(lane);
        if (answers && escaped)
        {
          answers[ray / 64] |= std::uint64_t(1) << (ray % 64);
        }
        if (escaped)
        {
          const double d[3] = { packet.DirectionX(lane), packet.DirectionY(lane),
            packet.DirectionZ(lane) };
          ++visible;
          sum[0] += d[0];
          sum[1] += d[1];
          sum[2] += d[2];
          cosSum += d[0] * nrm[0] + d[1] * nrm[1] + d[2] * nrm[2];
        }
      }
    }
    const double solidAngle = 2.0 * Pi * visible / n;
    this->Out.Radius[id] = static_cast<float>(vtkSphericalCap::CapRadiusFromSolidAngle(solidAngle));
    const double length = vtkMath::Norm(sum);
    for (int k = 0; k < 3; ++k)
    {
      // A closed aperture keeps the normal as its (defined) axis.
      this->Out.BentNormal[3 * id + k] =
        length > 0.0 ? static_cast<float>(sum[k] / length) : nrm[k];
    }
    if (!this->Out.Occlusion.empty())
    {
      // Uniform hemisphere samples: (1/pi) * integral of V cos = (2/n) * sum of V cos.
      this->Out.Occlusion[id] = static_cast<float>(std::min(1.0, 2.0 * cosSum / n));
    }
    return traced;
  }

  // The point's mask: RaysSide² rays on a sub-grid of each cell; open where half escape. Returns
  // how many rays it traced.
  vtkIdType CastMask(vtkApertureRayPacket& packet, vtkIdType id, std::vector<int>& seen,
    std::vector<float>& directions) const
  {
    const float* nrm = this->Surface.GetNormal(id);
    const double n[3] = { nrm[0], nrm[1], nrm[2] };
    const int side = this->Mask.Side, per = this->Mask.RaysSide, cells = side * side;
    const int rays = cells * per * per;
    vtkVisibilityMask::CellRayDirections(n, side, per, directions);
    std::fill(seen.begin(), seen.end(), 0);
    for (int first = 0; first < rays; first += Lanes)
    {
      for (int lane = 0; lane < Lanes; ++lane)
      {
        if (first + lane < rays)
        {
          packet.Set(lane, id, &directions[3 * (first + lane)], this->MaximumDistance);
        }
        else
        {
          packet.Clear(lane);
        }
      }
      packet.Trace();
      for (int lane = 0; lane < Lanes && first + lane < rays; ++lane)
      {
        seen[(first + lane) / (per * per)] += packet.Visible(lane) ? 1 : 0;
      }
    }
    unsigned char* bytes = &this->Out.Mask[static_cast<size_t>(id) * (cells / 8)];
    std::fill_n(bytes, cells / 8, 0);
    for (int cell = 0; cell < cells; ++cell)
    {
      bytes[cell / 8] |= 2 * seen[cell] >= per * per ? 1 << (cell % 8) : 0;
    }
    return rays;
  }

  const vtkApertureSurface& Surface;
  const vtkApertureRayScene& Scene;
  const vtkApertureRaySampler& Sampler;
  float MaximumDistance;
  MaskSettings Mask;
  const std::vector<unsigned char>& Needed;
  const vtkApertureHistory* History;
  Caps& Out;
  std::atomic<vtkIdType>& Traced;
  std::vector<std::uint32_t> Order;
};

// One dataset that gets caps: the input leaf (or its refinement), its output, and its surface.
struct Receiver
{
  vtkDataSet* Input;
  vtkDataSet* Output;
  vtkDataArray* Heights; // height fields only
  vtkSmartPointer<vtkPolyData> Refined;
  vtkSmartPointer<vtkPolyData> Ghosts; // other pieces' cells around a distributed piece
  vtkApertureSurface Surface;
  Caps Results;

  vtkDataSet* Source() const { return this->Refined ? this->Refined.Get() : this->Input; }
};

// The part `extent` of an image, with every point array: the grid a tile's output is.
void CopyExtent(vtkImageData* input, const int extent[6], vtkImageData* output)
{
  output->SetExtent(const_cast<int*>(extent));
  output->SetOrigin(input->GetOrigin());
  output->SetSpacing(input->GetSpacing());
  output->SetDirectionMatrix(input->GetDirectionMatrix());
  if (std::equal(extent, extent + 6, input->GetExtent()))
  {
    output->GetPointData()->ShallowCopy(input->GetPointData()); // not 4 bytes a texel more
  }
  else
  {
    output->GetPointData()->CopyAllocate(input->GetPointData(), output->GetNumberOfPoints());
    output->GetPointData()->CopyStructuredData(input->GetPointData(), input->GetExtent(), extent);
  }
  output->GetFieldData()->ShallowCopy(input->GetFieldData());
}

// Points on no polygon or strip look along their given normal, or +z.
void OpenAroundNormals(
  vtkFloatArray* bent, const std::vector<vtkIdType>& outputPoints, vtkDataArray* normals)
{
  for (size_t o = 0; o < outputPoints.size(); ++o)
  {
    double given[3] = { 0.0, 0.0, 1.0 };
    if (outputPoints[o] != vtkApertureSurface::NotOnSurface || !normals ||
      static_cast<vtkIdType>(o) >= normals->GetNumberOfTuples())
    {
      continue;
    }
    normals->GetTuple(static_cast<vtkIdType>(o), given);
    if (vtkMath::Normalize(given) > 0.0)
    {
      bent->SetTuple(static_cast<vtkIdType>(o), given);
    }
  }
}
}

//------------------------------------------------------------------------------
// The state of one RequestData, step by step.
class vtkAperturePrecompute::vtkRun
{
public:
  vtkRun(vtkAperturePrecompute* self, bool distributed)
    : Self(self)
    , Distributed(distributed)
  {
  }

  bool CollectReceivers(vtkDataObject* input, vtkDataObject* output);
  bool CheckReceivers();
  void CollectOccluders(vtkInformationVector* occluderInfo);
  bool ChooseMethod();
  bool SweepHorizons(const int extent[6]);
  bool FindTimeStep(vtkDataObject* input, vtkDataObject* output);
  void StoreTimeStep(vtkDataObject* output);
  bool Refine();
  bool BuildSurfaces();
  void PlanReuse();
  bool BuildScene();
  // Whether a moving surface keeps every point's caps (no ray to cast, no BVH to build).
  bool NothingToCast() const;
  bool Cast();
  void Remember();
  void WriteOutputs(const int* extent);
  void Warn();

  vtkAperturePrecompute* Self;
  const bool Distributed;  // one piece of several: the other ranks' surfaces occlude too
  bool EmptyPiece = false; // a piece without points, which gives an empty output
  std::vector<std::unique_ptr<Receiver>> Receivers;
  std::vector<vtkPolyData*> Occluders;
  vtkSmartPointer<vtkPolyData> RemoteOccluders;
  std::vector<vtkApertureSurface> OccluderSurfaces;
  // Given back after the rays: on a large surface the BVH is the largest part of a run.
  std::unique_ptr<vtkApertureRayScene> Scene{ new vtkApertureRayScene };
  vtkIdType TotalPoints = 0;
  vtkIdType NoData = 0;
  bool Horizons = false;
  bool Aborted = false;
  // A time step: its time, and the input pipeline's modification time.
  bool Temporal = false;
  double Time = 0.0;
  vtkMTimeType Pipeline = 0;
  // A moving surface: its input's coordinates and which receiving points cast rays.
  bool Reusable = false;
  std::vector<double> World;
  std::vector<unsigned char> Needed;
};

//------------------------------------------------------------------------------
// Receivers: the input itself, or every leaf of a composite input.
bool vtkAperturePrecompute::vtkRun::CollectReceivers(vtkDataObject* input, vtkDataObject* output)
{
  auto add = [&](vtkDataSet* in, vtkDataSet* out) {
    this->Receivers.emplace_back(new Receiver{ in, out, nullptr, nullptr, nullptr, {}, {} });
  };
  auto* compositeIn = vtkCompositeDataSet::SafeDownCast(input);
  if (!compositeIn)
  {
    add(vtkDataSet::SafeDownCast(input), vtkDataSet::SafeDownCast(output));
    return true;
  }
  auto* compositeOut = vtkCompositeDataSet::SafeDownCast(output);
  compositeOut->CopyStructure(compositeIn);
  auto it = vtk::TakeSmartPointer(compositeIn->NewIterator());
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
  {
    auto* leaf = vtkPolyData::SafeDownCast(it->GetCurrentDataObject());
    if (!leaf)
    {
      vtkErrorWithObjectMacro(this->Self,
        "Composite input must hold vtkPolyData leaves, found "
          << it->GetCurrentDataObject()->GetClassName() << ".");
      return false;
    }
    auto copy = vtkSmartPointer<vtkPolyData>::New();
    compositeOut->SetDataSet(it, copy);
    add(leaf, copy);
  }
  return true;
}

//------------------------------------------------------------------------------
// Checks the input before any work: grids, heights, cells, point ids.
bool vtkAperturePrecompute::vtkRun::CheckReceivers()
{
  vtkIdType surfaceCells = 0;
  for (const auto& r : this->Receivers)
  {
    this->TotalPoints += r->Input->GetNumberOfPoints();
    if (auto* image = vtkImageData::SafeDownCast(r->Input))
    {
      const int* dims = image->GetDimensions();
      if (dims[2] != 1 || dims[0] < 2 || dims[1] < 2)
      {
        vtkErrorWithObjectMacro(this->Self,
          "A height field must be a 2D grid of at least 2 x 2 points in the xy plane of its "
          "index space; got dimensions "
            << dims[0] << " x " << dims[1] << " x " << dims[2] << ".");
        return false;
      }
      r->Heights = this->Self->GetInputArrayToProcess(0, image);
      // An array chosen by an empty name (ParaView's, before its input had arrays): the scalars.
      vtkInformation* chosen = this->Self->GetInputArrayInformation(0);
      if (!r->Heights && chosen->Has(vtkDataObject::FIELD_NAME()) &&
        !*chosen->Get(vtkDataObject::FIELD_NAME()))
      {
        r->Heights = image->GetPointData()->GetScalars();
      }
      if (!r->Heights)
      {
        vtkErrorWithObjectMacro(
          this->Self, "The height field has no point scalars (or no array to process).");
        return false;
      }
      if (r->Heights->GetNumberOfComponents() != 1 ||
        r->Heights->GetNumberOfTuples() != image->GetNumberOfPoints())
      {
        vtkErrorWithObjectMacro(this->Self,
          "Height field scalars " << vtkApertureText::Quote(
                                       r->Heights->GetName() ? r->Heights->GetName() : "")
                                  << " must have one component and one value per point; they have "
                                  << r->Heights->GetNumberOfComponents() << " component(s) and "
                                  << r->Heights->GetNumberOfTuples() << " tuples.");
        return false;
      }
      surfaceCells += image->GetNumberOfCells();
    }
    else if (auto* poly = vtkPolyData::SafeDownCast(r->Input))
    {
      const std::string bad = vtkApertureCellCheck::FindBadCell(poly);
      if (!bad.empty())
      {
        vtkErrorWithObjectMacro(this->Self, "Cannot use the input: " << bad << ".");
        return false;
      }
      surfaceCells += poly->GetNumberOfPolys() + poly->GetNumberOfStrips();
    }
  }
  if (this->TotalPoints == 0 && this->Distributed)
  {
    this->EmptyPiece = true;
    return true;
  }
  if (this->TotalPoints == 0)
  {
    vtkErrorWithObjectMacro(
      this->Self, "The input is empty: there are no points to compute apertures for.");
    return false;
  }
  if (surfaceCells == 0)
  {
    vtkErrorWithObjectMacro(
      this->Self, "The input has no polygons or triangle strips: nothing casts or receives rays.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
// The occluder port's surfaces and, in a distributed run on surfaces, the other ranks' (a
// collective step, so it comes before any check can fail).
void vtkAperturePrecompute::vtkRun::CollectOccluders(vtkInformationVector* occluderInfo)
{
  this->Occluders = vtkApertureDistributedOccluders::Occluders(occluderInfo, nullptr);
  std::vector<vtkPolyData*> local;
  for (const auto& r : this->Receivers)
  {
    if (auto* poly = vtkPolyData::SafeDownCast(r->Input))
    {
      local.push_back(poly);
    }
  }
  const bool heightField =
    this->Receivers.size() == 1 && vtkImageData::SafeDownCast(this->Receivers[0]->Input);
  if (this->Distributed && !heightField)
  {
    this->RemoteOccluders = vtkApertureDistributedOccluders::Gather(
      this->Self->Controller, local, this->Self->SearchDistance());
    if (local.size() == 1 && this->Receivers.size() == 1)
    {
      this->Receivers[0]->Ghosts =
        vtkApertureDistributedOccluders::TakeGhosts(local[0], this->RemoteOccluders);
    }
    if (this->RemoteOccluders->GetNumberOfCells() > 0)
    {
      this->Occluders.push_back(this->RemoteOccluders);
    }
  }
}

//------------------------------------------------------------------------------
// A time step computed before (serial runs): its output, and true. Empties what earlier updates
// kept when the settings or the occluders changed.
bool vtkAperturePrecompute::vtkRun::FindTimeStep(vtkDataObject* input, vtkDataObject* output)
{
  vtkAperturePrecompute* self = this->Self;
  self->LastUpdate = COMPUTED;
  self->NumberOfReusedPoints = 0;
  // The settings' values, not the filter's modification time: a new input connection or
  // input data modifies the filter, and is what a time series or a moving surface brings.
  std::ostringstream key;
  key.precision(17);
  self->PrintSettings(key, vtkIndent());
  for (vtkPolyData* occluder : this->Occluders)
  {
    key << occluder << " " << occluder->GetMTime() << "\n";
  }
  self->History->SetKey(key.str());
  vtkInformation* info = input->GetInformation();
  this->Temporal =
    !this->Distributed && self->TimeStepCacheSize > 0 && info->Has(vtkDataObject::DATA_TIME_STEP());
  if (!this->Temporal)
  {
    return false;
  }
  this->Time = info->Get(vtkDataObject::DATA_TIME_STEP());
  auto* executive = vtkDemandDrivenPipeline::SafeDownCast(self->GetInputExecutive(0, 0));
  this->Pipeline = executive ? executive->GetPipelineMTime() : input->GetMTime();
  vtkDataObject* step = self->History->Find(this->Time, this->Pipeline);
  if (step)
  {
    output->ShallowCopy(step);
    self->LastUpdate = CACHED_TIME_STEP;
    self->NumberOfSurfacePoints = 0;
    self->NumberOfReusedPoints = 0;
  }
  return step != nullptr;
}

//------------------------------------------------------------------------------
void vtkAperturePrecompute::vtkRun::StoreTimeStep(vtkDataObject* output)
{
  if (this->Temporal)
  {
    this->Self->History->Store(this->Time, this->Pipeline, output, this->Self->TimeStepCacheSize);
  }
}

//------------------------------------------------------------------------------
// Horizon sweeps for one height field without occluders; rays for everything else.
bool vtkAperturePrecompute::vtkRun::ChooseMethod()
{
  const bool heightField =
    this->Receivers.size() == 1 && vtkImageData::SafeDownCast(this->Receivers[0]->Input);
  const bool possible = heightField && this->Occluders.empty();
  if (this->Self->Method == HORIZONS && !possible)
  {
    vtkErrorWithObjectMacro(this->Self,
      "Horizon sweeps need a height field (vtkImageData) and no occluders; "
        << (heightField ? "there are occluders." : "the input is not a height field."));
    return false;
  }
  this->Horizons = possible && this->Self->Method != RAYS;
  const int rays = this->Self->VisibilityMaskRaysPerCell;
  if (this->Self->ComputeVisibilityMask && !this->Horizons &&
    (!vtkVisibilityMask::IsValidBitCount(this->Self->VisibilityMaskBits) ||
      !(rays == 1 || rays == 4 || rays == 9 || rays == 16)))
  {
    vtkErrorWithObjectMacro(this->Self,
      "A visibility mask has 64, 144, 256, 400, 576, 784 or 1024 cells and 1, 4, 9 or 16 rays a "
      "cell, not "
        << this->Self->VisibilityMaskBits << " cells and " << rays << " rays.");
    return false;
  }
  if (this->Self->ComputeVisibilityMask && this->Horizons)
  {
    vtkWarningWithObjectMacro(this->Self,
      "A visibility mask comes from rays; this update sweeps horizons, so there is no "
        << vtkApertureText::Quote(this->Self->VisibilityMaskArrayName)
        << " array (SetMethodToRays() casts rays on a height field).");
  }
  if (this->Self->ComputeHorizonAngles && !this->Horizons)
  {
    vtkWarningWithObjectMacro(this->Self,
      "Horizon angles come from horizon sweeps of a height field; this update casts rays, so "
      "there is no "
        << vtkApertureText::Quote(this->Self->HorizonAnglesArrayName) << " array.");
  }
  const vtkAperturePrecompute* self = this->Self;
  if ((self->ComputeSkyViewFactor || self->ComputeSkyViewFactorCosine ||
        self->ComputePositiveOpenness || self->ComputeNegativeOpenness) &&
    !this->Horizons)
  {
    vtkWarningWithObjectMacro(this->Self,
      "Sky-view factors and openness come from horizon sweeps of a height field; this update "
      "casts rays, so there are none.");
  }
  if (self->NoDataAs != NO_DATA_OPEN && !this->Horizons)
  {
    vtkWarningWithObjectMacro(this->Self,
      "No-data as walls or filled applies to horizon sweeps; this update casts rays, where "
      "no-data stays open.");
  }
  if (self->EarthRadius > 0.0 && !this->Horizons)
  {
    vtkWarningWithObjectMacro(this->Self,
      "The Earth's curvature applies to horizon sweeps; this update casts rays over the ground "
      "as it is.");
  }
  if (!std::isfinite(self->SectorRotation))
  {
    vtkErrorWithObjectMacro(this->Self, "The sector rotation must be finite.");
    return false;
  }
  if (!(self->EarthRadius >= 0.0 && self->EarthRadius < VTK_DOUBLE_MAX))
  {
    vtkErrorWithObjectMacro(this->Self,
      "The Earth radius must be 0 (flat ground) or positive and finite, not " << self->EarthRadius
                                                                              << ".");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
// The caps of the output extent from the horizons over the whole input extent.
bool vtkAperturePrecompute::vtkRun::SweepHorizons(const int extent[6])
{
  vtkAperturePrecompute* self = this->Self;
  Receiver& r = *this->Receivers[0];
  auto* image = vtkImageData::SafeDownCast(r.Input);
  auto* output = vtkImageData::SafeDownCast(r.Output);
  CopyExtent(image, extent, output);
  vtkHorizonHeightField::Settings settings;
  settings.HeightScale = self->HeightScale;
  settings.Sectors = self->NumberOfSectors;
  settings.MaximumDistance = self->SearchDistance();
  settings.AmbientOcclusion = self->ComputeAmbientOcclusion;
  settings.Normals = self->ComputeNormals;
  settings.Horizons = self->ComputeHorizonAngles;
  settings.HorizonName = self->HorizonAnglesArrayName.c_str();
  settings.SkyViewFactor = self->ComputeSkyViewFactor;
  settings.SkyViewFactorCosine = self->ComputeSkyViewFactorCosine;
  settings.PositiveOpenness = self->ComputePositiveOpenness;
  settings.NegativeOpenness = self->ComputeNegativeOpenness;
  settings.SectorRotation = self->SectorRotation;
  settings.EarthRadius = self->EarthRadius;
  settings.NoDataAs = self->NoDataAs;
  settings.WallHeight = self->NoDataWallHeight;
  settings.FillDistance = self->NoDataFillDistance;
  settings.BentNormalName = self->BentNormalArrayName.c_str();
  settings.RadiusName = self->ApertureRadiusArrayName.c_str();
  settings.OcclusionName = self->AmbientOcclusionArrayName.c_str();
  self->UpdateProgress(0.0);
  auto progress = [self](double fraction)
  {
    self->UpdateProgress(fraction);
    return !self->GetAbortExecute();
  };
  std::string error;
  this->NoData = vtkHorizonHeightField::Compute(
    image, r.Heights, extent, settings, output->GetPointData(), error, progress);
  if (this->NoData < 0)
  {
    this->Aborted = self->GetAbortExecute() != 0;
    if (!this->Aborted)
    {
      vtkErrorWithObjectMacro(self, "Cannot sweep the horizons: " << error);
    }
    return this->Aborted;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkAperturePrecompute::vtkRun::Refine()
{
  const double length = this->Self->GetMaximumEdgeLength();
  for (const auto& r : this->Receivers)
  {
    auto* poly = vtkPolyData::SafeDownCast(r->Input);
    if (length <= 0.0 || !poly)
    {
      continue;
    }
    r->Refined = vtkSmartPointer<vtkPolyData>::New();
    std::string error;
    if (!vtkApertureRefinement::Refine(poly, length, r->Refined, error))
    {
      vtkErrorWithObjectMacro(this->Self, "Cannot refine the input: " << error << ".");
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkAperturePrecompute::vtkRun::BuildSurfaces()
{
  vtkAperturePrecompute* self = this->Self;
  std::vector<vtkApertureSceneSurfaces::Receiver> receivers;
  for (const auto& r : this->Receivers)
  {
    receivers.push_back({ r->Source(), r->Heights, &r->Surface, r->Ghosts });
  }
  vtkApertureSceneSurfaces::Settings settings;
  settings.FeatureAngle = self->FeatureAngle;
  settings.RayOffset = self->RayOffset;
  settings.HeightScale = self->HeightScale;
  std::string error;
  if (!vtkApertureSceneSurfaces::Build(
        receivers, this->Occluders, settings, this->OccluderSurfaces, error))
  {
    vtkErrorWithObjectMacro(self, << error);
    return false;
  }
  if (!self->KeyRaysByPointId)
  {
    return true;
  }
  for (const auto& r : this->Receivers)
  {
    vtkDataArray* ids = r->Source()->GetPointData()->GetGlobalIds();
    const bool fits = ids && ids->GetNumberOfComponents() == 1 &&
      ids->GetNumberOfTuples() == r->Source()->GetNumberOfPoints();
    r->Surface.KeyByPointIds(fits ? ids : nullptr);
  }
  return true;
}

//------------------------------------------------------------------------------
// A moving surface: which receiving points cast rays again. All of them, unless the last
// update's surface had the same cells (one polydata, serial, not refined) and the reach of
// the rays is bounded.
void vtkAperturePrecompute::vtkRun::PlanReuse()
{
  vtkAperturePrecompute* self = this->Self;
  Receiver* r = this->Receivers.size() == 1 ? this->Receivers[0].get() : nullptr;
  auto* poly = r && !r->Refined ? vtkPolyData::SafeDownCast(r->Input) : nullptr;
  this->Reusable = self->ReuseUnmovedPoints && poly && !this->Distributed;
  if (!this->Reusable)
  {
    return;
  }
  vtkApertureSurface::WorldPoints(poly->GetPoints(), this->World);
  if (vtkDataArray* normals = vtkApertureSurface::GivenNormals(poly))
  {
    // A turned normal changes its point's caps as a move does.
    std::vector<double> both(2 * this->World.size());
    for (vtkIdType i = 0; i < poly->GetNumberOfPoints(); ++i)
    {
      std::copy_n(&this->World[3 * i], 3, &both[6 * i]);
      normals->GetTuple(i, &both[6 * i + 3]);
    }
    this->World.swap(both);
  }
  const std::vector<float>& offsets = r->Surface.Offset;
  const double offset = offsets.empty() ? 0.0 : *std::max_element(offsets.begin(), offsets.end());
  // A ray starts up to 2 offsets from its point, and is traced from a quarter offset behind.
  const double reach = self->SearchDistance() + 3.0 * offset;
  this->Needed = self->History->Needed(r->Surface, this->World, reach);
  const vtkApertureHistory::Match match = self->History->GetMatch();
  if (match != vtkApertureHistory::NO_SURFACE)
  {
    self->LastUpdate = match == vtkApertureHistory::SAME_CELLS ? MOVED_POINTS : NEW_TOPOLOGY;
  }
  self->NumberOfReusedPoints =
    std::count(this->Needed.begin(), this->Needed.end(), vtkApertureHistory::REUSE);
}

//------------------------------------------------------------------------------
bool vtkAperturePrecompute::vtkRun::BuildScene()
{
  if (this->NothingToCast())
  {
    return true; // a moving surface of which nothing moved: no BVH to build
  }
  std::vector<const vtkApertureSurface*> receivers, occluders;
  for (const auto& r : this->Receivers)
  {
    receivers.push_back(&r->Surface);
  }
  for (const auto& s : this->OccluderSurfaces)
  {
    occluders.push_back(&s);
  }
  if (this->Reusable)
  {
    // Only the triangles the points that cast again can reach: a smaller BVH and hit filter.
    const vtkApertureSurface& surface = this->Receivers[0]->Surface;
    this->Scene->KeepOnly(surface, this->Self->History->Reachable(surface));
  }
  if (!this->Scene->Build(
        receivers, occluders, this->Self->AccelerationStructure, this->Self->EmbreeConfiguration))
  {
    vtkErrorWithObjectMacro(this->Self, "Embree failed: " << this->Scene->GetError());
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkAperturePrecompute::vtkRun::NothingToCast() const
{
  return this->Reusable &&
    this->Self->NumberOfReusedPoints == static_cast<vtkIdType>(this->Needed.size());
}

//------------------------------------------------------------------------------
// Rays, in batches of about a million so that progress and aborts are seen often.
bool vtkAperturePrecompute::vtkRun::Cast()
{
  vtkAperturePrecompute* self = this->Self;
  const vtkApertureRaySampler sampler(self->NumberOfRays, self->Seed, self->Sampling == RANDOM);
  const vtkIdType batch = std::max<vtkIdType>(64, (1 << 20) / self->NumberOfRays);
  const float maximumDistance = self->SearchDistance() >= FLT_MAX
    ? std::numeric_limits<float>::infinity()
    : static_cast<float>(self->SearchDistance());
  MaskSettings mask;
  if (self->ComputeVisibilityMask)
  {
    mask.Side = vtkVisibilityMask::GetSide(self->VisibilityMaskBits);
    mask.RaysSide = static_cast<int>(std::lround(std::sqrt(self->VisibilityMaskRaysPerCell)));
  }
  vtkIdType casting = 0;
  for (const auto& r : this->Receivers)
  {
    casting += r->Surface.GetNumberOfPoints();
  }
  casting = this->Reusable ? casting - self->NumberOfReusedPoints : casting;
  self->NumberOfSurfacePoints = casting;
  const std::vector<unsigned char> all; // CastRays: every point
  const std::vector<unsigned char>& needed = this->Reusable ? this->Needed : all;
  std::atomic<vtkIdType> traced(0);
  vtkIdType done = 0;
  self->UpdateProgress(0.0);
  std::string error;
  for (const auto& r : this->Receivers)
  {
    const vtkIdType n = r->Surface.GetNumberOfPoints();
    r->Results.BentNormal.resize(3 * n);
    r->Results.Radius.resize(n);
    r->Results.Occlusion.assign(self->ComputeAmbientOcclusion ? n : 0, 0.0f);
    r->Results.Mask.assign(mask.Side > 0 ? n * mask.Side * mask.Side / 8 : 0, 0);
    // A moving surface keeps each ray's answer for the next update.
    r->Results.RayWords = this->Reusable ? (self->NumberOfRays + 63) / 64 : 0;
    r->Results.Rays.assign(size_t(n) * r->Results.RayWords, 0);
    if (this->NothingToCast())
    {
      continue; // Remember() copies every cap
    }
    const CastRays cast(r->Surface, *this->Scene, sampler, maximumDistance, mask, needed,
      self->History.get(), r->Results, traced);
    auto progress = [&](vtkIdType traced)
    {
      self->UpdateProgress(static_cast<double>(done + traced) / std::max<vtkIdType>(casting, 1));
      return !self->GetAbortExecute();
    };
    if (!this->Scene->TraceInBatches(cast.GetNumberOfPoints(), batch, 16, cast, progress, error))
    {
      vtkErrorWithObjectMacro(self, "Embree failed while tracing: " << error);
      return false;
    }
    this->Aborted = self->GetAbortExecute() != 0;
    if (this->Aborted)
    {
      return true;
    }
    done += cast.GetNumberOfPoints();
    self->NumberOfRaysTraced = traced;
  }
  this->Scene.reset();
  return true;
}

//------------------------------------------------------------------------------
// A moving surface of fixed cells: the caps of the points that did not cast rays again, and
// this update's surface for the next.
void vtkAperturePrecompute::vtkRun::Remember()
{
  vtkApertureHistory& history = *this->Self->History;
  if (!this->Reusable)
  {
    history.Forget();
    return;
  }
  Receiver& r = *this->Receivers[0];
  history.Reuse(r.Results);
  history.Remember(r.Surface, std::move(this->World), r.Results);
}

//------------------------------------------------------------------------------
// Each receiver's output: its input (split at creases, or refined) with the caps per point.
void vtkAperturePrecompute::vtkRun::WriteOutputs(const int* extent)
{
  vtkAperturePrecompute* self = this->Self;
  const float openRadius = static_cast<float>(0.5 * Pi), closedRadius = 0.0f;
  const float openOcclusion = 1.0f, closedOcclusion = 0.0f;
  const float up[3] = { 0.0f, 0.0f, 1.0f };
  for (const auto& r : this->Receivers)
  {
    std::vector<vtkIdType> points;
    if (auto* poly = vtkPolyData::SafeDownCast(r->Source()))
    {
      vtkApertureSurfaceOutput::Make(
        r->Surface, poly, vtkPolyData::SafeDownCast(r->Output), points);
    }
    else
    {
      r->Output->ShallowCopy(r->Input);
      points = r->Surface.InputPoints;
    }
    const Caps& c = r->Results;
    vtkPointData* pd = r->Output->GetPointData();
    auto bent = vtkApertureSurfaceOutput::Scatter(self->BentNormalArrayName, 3, c.BentNormal.data(),
      c.BentNormal.data() + c.BentNormal.size(), points, up, up);
    OpenAroundNormals(bent, points, r->Source()->GetPointData()->GetNormals());
    pd->AddArray(bent);
    pd->AddArray(vtkApertureSurfaceOutput::Scatter(self->ApertureRadiusArrayName, 1,
      c.Radius.data(), c.Radius.data() + c.Radius.size(), points, &openRadius, &closedRadius));
    if (!c.Occlusion.empty())
    {
      pd->AddArray(
        vtkApertureSurfaceOutput::Scatter(self->AmbientOcclusionArrayName, 1, c.Occlusion.data(),
          c.Occlusion.data() + c.Occlusion.size(), points, &openOcclusion, &closedOcclusion));
    }
    if (!c.Mask.empty())
    {
      const int bytes = self->VisibilityMaskBits / 8;
      const std::vector<unsigned char> open(bytes, 255), closed(bytes, 0);
      pd->AddArray(vtkApertureSurfaceOutput::Scatter(self->VisibilityMaskArrayName, bytes,
        c.Mask.data(), c.Mask.data() + c.Mask.size(), points, open.data(), closed.data()));
    }
    if (self->ComputeNormals)
    {
      vtkApertureSurfaceOutput::AddComputedNormals(r->Surface, pd, points);
    }
    // A tile: the input's halo cast rays, the output is the tile.
    auto* image = vtkImageData::SafeDownCast(r->Output);
    if (image && extent && !std::equal(extent, extent + 6, image->GetExtent()))
    {
      vtkNew<vtkImageData> whole;
      whole->ShallowCopy(image);
      CopyExtent(whole, extent, image);
    }
  }
}

//------------------------------------------------------------------------------
void vtkAperturePrecompute::vtkRun::Warn()
{
  if (this->NoData > 0)
  {
    static const char* const treatments[] = { "they neither occlude nor receive",
      "they occlude as walls but receive nothing", "no valid texel was near enough to fill them" };
    vtkWarningWithObjectMacro(this->Self,
      << this->NoData << " texel(s) are no-data (not finite, or masked); "
      << treatments[this->Self->NoDataAs] << " (vtkValidPointMask 0, closed aperture).");
  }
  vtkIdType nonFinite = 0, undefinedNormals = 0, flipped = 0;
  for (const auto& r : this->Receivers)
  {
    nonFinite += r->Surface.UnusablePoints;
    undefinedNormals += r->Surface.UndefinedNormals;
    flipped += r->Surface.FlippedNormals;
  }
  if (nonFinite > 0)
  {
    vtkWarningWithObjectMacro(
      this->Self, << nonFinite
                  << " point(s) are not finite (NaN, infinite or larger than 1e16); they get a "
                     "closed aperture and no cell that uses them casts shadows.");
  }
  if (undefinedNormals > 0)
  {
    vtkWarningWithObjectMacro(this->Self, << undefinedNormals
                                          << " point(s) have no defined normal (only degenerate "
                                             "cells use them); they get a closed aperture.");
  }
  if (flipped > 0)
  {
    vtkWarningWithObjectMacro(
      this->Self, << flipped
                  << " given normal(s) point against the winding of their cells; "
                     "their apertures face the way the normals do.");
  }
}

//------------------------------------------------------------------------------
vtkAperturePrecompute::vtkAperturePrecompute()
{
  this->SetNumberOfInputPorts(2);
  // Height fields: heights are the active point scalars unless another array is chosen.
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS);
  this->SetController(vtkMultiProcessController::GetGlobalController());
  this->History.reset(new vtkApertureHistory);
}

//------------------------------------------------------------------------------
vtkAperturePrecompute::~vtkAperturePrecompute()
{
  this->SetController(nullptr);
}

//------------------------------------------------------------------------------
vtkCxxSetObjectMacro(vtkAperturePrecompute, Controller, vtkMultiProcessController);

//------------------------------------------------------------------------------
void vtkAperturePrecompute::AddOccluderConnection(vtkAlgorithmOutput* output)
{
  this->AddInputConnection(1, output);
}

//------------------------------------------------------------------------------
void vtkAperturePrecompute::AddOccluderData(vtkDataObject* data)
{
  this->AddInputDataInternal(1, data);
}

//------------------------------------------------------------------------------
void vtkAperturePrecompute::RemoveAllOccluders()
{
  this->SetInputConnection(1, nullptr);
}

//------------------------------------------------------------------------------
int vtkAperturePrecompute::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 0)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
    info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
    info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
    return 1;
  }
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  info->Set(vtkAlgorithm::INPUT_IS_REPEATABLE(), 1);
  return 1;
}

//------------------------------------------------------------------------------
int vtkAperturePrecompute::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  using SDDP = vtkStreamingDemandDrivenPipeline;
  if (!inInfo || !outInfo->Has(SDDP::UPDATE_EXTENT()) || !inInfo->Has(SDDP::WHOLE_EXTENT()) ||
    !inInfo->Has(vtkDataObject::SPACING()))
  {
    return 1; // not a grid: the executive passes the request on
  }
  int extent[6], whole[6];
  outInfo->Get(SDDP::UPDATE_EXTENT(), extent);
  inInfo->Get(SDDP::WHOLE_EXTENT(), whole);
  // One piece of several (a rank of a distributed run): the piece's extent is made here, from
  // its input's extent grown by the halo; a piece of the input's own would have no halo.
  const int pieces = outInfo->Has(SDDP::UPDATE_NUMBER_OF_PIECES())
    ? outInfo->Get(SDDP::UPDATE_NUMBER_OF_PIECES())
    : 1;
  if (pieces > 1)
  {
    vtkNew<vtkExtentTranslator> translator;
    translator->PieceToExtentThreadSafe(outInfo->Get(SDDP::UPDATE_PIECE_NUMBER()), pieces, 0, whole,
      extent, vtkExtentTranslator::BLOCK_MODE, 0);
    outInfo->Set(SDDP::UPDATE_EXTENT(), extent, 6);
    inInfo->Set(SDDP::UPDATE_PIECE_NUMBER(), 0);
    inInfo->Set(SDDP::UPDATE_NUMBER_OF_PIECES(), 1);
  }
  if (extent[1] < extent[0] || extent[3] < extent[2])
  {
    inInfo->Set(SDDP::UPDATE_EXTENT(), extent, 6); // an empty piece needs nothing
    return 1;
  }
  const int halo =
    vtkHorizonHeightField::Halo(this->SearchDistance(), inInfo->Get(vtkDataObject::SPACING()),
      this->NoDataAs == NO_DATA_FILL ? this->NoDataFillDistance : 0);
  for (int k = 0; k < 6; ++k)
  {
    const bool grows = k < 4 && halo >= 0;
    const int grown =
      k % 2 ? std::min(whole[k], extent[k] + halo) : std::max(whole[k], extent[k] - halo);
    extent[k] = grows ? grown : whole[k];
  }
  inInfo->Set(SDDP::UPDATE_EXTENT(), extent, 6);
  return 1;
}

//------------------------------------------------------------------------------
int vtkAperturePrecompute::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  const int done = this->Compute(inputVector, outputVector);
  if (!vtkApertureDistributedOccluders::IsDistributed(
        this->Controller, outputVector->GetInformationObject(0)))
  {
    return done;
  }
  // Every rank fails when one does, and says which: a piece missing from the whole is no
  // answer, and the other ranks would otherwise not know.
  std::string failed;
  if (vtkApertureDistributedOccluders::AllSucceeded(this->Controller, done != 0, failed))
  {
    return done;
  }
  if (done)
  {
    vtkErrorMacro("Rank(s) " << failed << " failed (their errors say why); this rank's piece is "
                             << "left empty too.");
    vtkDataObject::GetData(outputVector, 0)->Initialize();
  }
  return 0;
}

//------------------------------------------------------------------------------
int vtkAperturePrecompute::Compute(
  vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
  vtkDataObject* output = vtkDataObject::GetData(outputVector, 0);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  const int* extent = vtkImageData::SafeDownCast(output) &&
      outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT())
    ? outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT())
    : nullptr;
  this->NumberOfSurfacePoints = 0;
  this->NumberOfRaysTraced = 0;
  this->UsedHorizons = false;
  if (!input || !output)
  {
    vtkErrorMacro("Missing input or output.");
    return 0;
  }
  if (extent && (extent[1] < extent[0] || extent[3] < extent[2]))
  {
    output->Initialize(); // an empty piece
    return 1;
  }
  auto* image = vtkImageData::SafeDownCast(input);
  const int* got = image ? image->GetExtent() : nullptr;
  if (got && extent &&
    (extent[0] < got[0] || extent[1] > got[1] || extent[2] < got[2] || extent[3] > got[3]))
  {
    vtkErrorMacro("The input holds texels " << got[0] << ".." << got[1] << " x " << got[2] << ".."
                                            << got[3] << ", not all of the extent asked for.");
    return 0;
  }
  // 1. Receivers and occluders, checked before any work; horizons or rays.
  vtkRun run(this, vtkApertureDistributedOccluders::IsDistributed(this->Controller, outInfo));
  bool ok = run.CollectReceivers(input, output);
  run.CollectOccluders(inputVector[1]);
  if (ok && run.FindTimeStep(input, output))
  {
    return 1;
  }
  ok = ok && run.CheckReceivers();
  if (ok && run.EmptyPiece)
  {
    output->Initialize();
    return 1;
  }
  ok = ok && run.ChooseMethod();
  this->UsedHorizons = ok && run.Horizons;
  if (ok && run.Horizons)
  {
    // 2. The height field's horizons, straight to the output extent's caps.
    ok = run.SweepHorizons(extent ? extent : got);
  }
  else if (ok)
  {
    // 2. The surfaces (refined, welded, split at creases), one Embree scene, and the rays of
    // every receiving point; the caps on the output's points.
    ok = run.Refine() && run.BuildSurfaces();
    if (ok)
    {
      run.PlanReuse();
    }
    ok = ok && run.BuildScene() && run.Cast();
    if (ok && !run.Aborted)
    {
      run.Remember();
      run.WriteOutputs(extent);
    }
  }
  if (!ok || run.Aborted)
  {
    output->Initialize();
    return ok ? 1 : 0;
  }
  // 3. What the caps could not be computed for; the step for a later visit.
  run.Warn();
  run.StoreTimeStep(output);
  return 1;
}

//------------------------------------------------------------------------------
double vtkAperturePrecompute::SearchDistance() const
{
  return this->LimitDistance ? this->MaximumDistance : VTK_DOUBLE_MAX;
}

//------------------------------------------------------------------------------
void vtkAperturePrecompute::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  this->PrintSettings(os, indent);
  os << indent << "UsedHorizons: " << this->UsedHorizons << "\n";
  os << indent << "NumberOfOccluders: " << this->GetNumberOfInputConnections(1) << "\n";
  os << indent << "Controller: " << this->Controller << "\n";
  os << indent << "NumberOfSurfacePoints: " << this->NumberOfSurfacePoints << "\n";
  static const char* const updates[] = { "Computed", "CachedTimeStep", "MovedPoints",
    "NewTopology" };
  os << indent << "LastUpdate: " << updates[this->LastUpdate] << "\n";
  os << indent << "NumberOfReusedPoints: " << this->NumberOfReusedPoints << "\n";
  os << indent << "NumberOfRaysTraced: " << this->NumberOfRaysTraced << "\n";
}

//------------------------------------------------------------------------------
void vtkAperturePrecompute::PrintSettings(ostream& os, vtkIndent indent)
{
  static const char* const structures[] = { "Automatic", "Compact", "Fast" };
  os << indent << "NumberOfRays: " << this->NumberOfRays << "\n";
  os << indent << "LimitDistance: " << (this->LimitDistance ? "On" : "Off") << "\n";
  os << indent << "MaximumDistance: " << this->MaximumDistance << "\n";
  os << indent << "RayOffset: " << this->RayOffset << "\n";
  os << indent << "Seed: " << this->Seed << "\n";
  os << indent << "Sampling: " << (this->Sampling == RANDOM ? "Random" : "Stratified") << "\n";
  os << indent << "HeightScale: " << this->HeightScale << "\n";
  vtkInformation* heights = this->GetInputArrayInformation(0);
  os << indent << "Heights: "
     << (heights->Has(vtkDataObject::FIELD_NAME()) ? heights->Get(vtkDataObject::FIELD_NAME())
                                                   : "(scalars)")
     << "\n";
  os << indent << "ComputeAmbientOcclusion: " << this->ComputeAmbientOcclusion << "\n";
  os << indent << "ComputeNormals: " << this->ComputeNormals << "\n";
  os << indent << "ComputeHorizonAngles: " << this->ComputeHorizonAngles << "\n";
  os << indent << "ComputeSkyViewFactor: " << this->ComputeSkyViewFactor << "\n";
  os << indent << "ComputeSkyViewFactorCosine: " << this->ComputeSkyViewFactorCosine << "\n";
  os << indent << "ComputePositiveOpenness: " << this->ComputePositiveOpenness << "\n";
  os << indent << "ComputeNegativeOpenness: " << this->ComputeNegativeOpenness << "\n";
  os << indent << "SectorRotation: " << this->SectorRotation << "\n";
  os << indent << "EarthRadius: " << this->EarthRadius << "\n";
  static const char* const noData[] = { "Open", "Wall", "Fill" };
  os << indent << "NoDataAs: " << noData[this->NoDataAs] << "\n";
  os << indent << "NoDataWallHeight: " << this->NoDataWallHeight << "\n";
  os << indent << "NoDataFillDistance: " << this->NoDataFillDistance << "\n";
  os << indent << "ComputeVisibilityMask: " << this->ComputeVisibilityMask << "\n";
  os << indent << "VisibilityMaskBits: " << this->VisibilityMaskBits << "\n";
  os << indent << "VisibilityMaskRaysPerCell: " << this->VisibilityMaskRaysPerCell << "\n";
  os << indent << "FeatureAngle: " << this->FeatureAngle << "\n";
  os << indent << "MaximumEdgeLength: " << this->MaximumEdgeLength << "\n";
  os << indent << "BentNormalArrayName: " << this->BentNormalArrayName << "\n";
  os << indent << "ApertureRadiusArrayName: " << this->ApertureRadiusArrayName << "\n";
  os << indent << "AmbientOcclusionArrayName: " << this->AmbientOcclusionArrayName << "\n";
  os << indent << "HorizonAnglesArrayName: " << this->HorizonAnglesArrayName << "\n";
  os << indent << "VisibilityMaskArrayName: " << this->VisibilityMaskArrayName << "\n";
  os << indent << "AccelerationStructure: " << structures[this->AccelerationStructure] << "\n";
  static const char* const methods[] = { "HorizonsForHeightFields", "Rays", "Horizons" };
  os << indent << "Method: " << methods[this->Method] << "\n";
  os << indent << "NumberOfSectors: " << this->NumberOfSectors << "\n";
  os << indent << "EmbreeConfiguration: " << this->EmbreeConfiguration << "\n";
  os << indent << "TimeStepCacheSize: " << this->TimeStepCacheSize << "\n";
  os << indent << "ReuseUnmovedPoints: " << (this->ReuseUnmovedPoints ? "On" : "Off") << "\n";
  os << indent << "KeyRaysByPointId: " << (this->KeyRaysByPointId ? "On" : "Off") << "\n";
}
