/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureDistributedOccluders.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkApertureDistributedOccluders.h"

#include "vtkApertureCellCheck.h"
#include "vtkAppendPolyData.h"
#include "vtkBoundingBox.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <array>
#include <limits>

namespace
{
// Bounds of the finite points of valid pieces (uninitialised when there are none).
vtkBoundingBox LocalBounds(const std::vector<vtkPolyData*>& pieces)
{
  vtkBoundingBox box;
  for (vtkPolyData* piece : pieces)
  {
    vtkPoints* points = piece->GetPoints();
    for (vtkIdType i = 0; points && i < points->GetNumberOfPoints(); ++i)
    {
      double p[3];
      points->GetPoint(i, p);
      if (vtkMath::IsFinite(p[0]) && vtkMath::IsFinite(p[1]) && vtkMath::IsFinite(p[2]))
      {
        box.AddPoint(p);
      }
    }
  }
  return box;
}

// Whether a cell's points come within the boxes (each already grown by the maximum distance).
bool NearAny(
  vtkPoints* points, vtkIdType size, const vtkIdType* ids, const std::vector<vtkBoundingBox>& boxes)
{
  vtkBoundingBox cell;
  for (vtkIdType k = 0; k < size; ++k)
  {
    double p[3];
    points->GetPoint(ids[k], p);
    cell.AddPoint(p);
  }
  for (const vtkBoundingBox& box : boxes)
  {
    if (box.Intersects(cell))
    {
      return true;
    }
  }
  return false;
}

// The cells near any of the boxes (all of them when `all`).
vtkSmartPointer<vtkCellArray> KeepCells(
  vtkCellArray* cells, vtkPoints* points, bool all, const std::vector<vtkBoundingBox>& boxes)
{
  auto kept = vtkSmartPointer<vtkCellArray>::New();
  auto it = vtk::TakeSmartPointer(cells->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    it->GetCurrentCell(size, ids);
    if (all || NearAny(points, size, ids, boxes))
    {
      kept->InsertNextCell(size, ids);
    }
  }
  return kept;
}

// A piece's polygons and strips on its points, without arrays.
vtkSmartPointer<vtkPolyData> Surface(
  vtkPolyData* piece, bool all, const std::vector<vtkBoundingBox>& boxes)
{
  auto surface = vtkSmartPointer<vtkPolyData>::New();
  surface->SetPoints(piece->GetPoints());
  surface->SetPolys(KeepCells(piece->GetPolys(), piece->GetPoints(), all, boxes));
  surface->SetStrips(KeepCells(piece->GetStrips(), piece->GetPoints(), all, boxes));
  return surface;
}

// The positions of a piece's finite points, sorted, for exact look-ups.
std::vector<std::array<double, 3>> SortedPositions(vtkPoints* points)
{
  std::vector<std::array<double, 3>> positions;
  for (vtkIdType i = 0; points && i < points->GetNumberOfPoints(); ++i)
  {
    std::array<double, 3> p;
    points->GetPoint(i, p.data());
    if (vtkMath::IsFinite(p[0]) && vtkMath::IsFinite(p[1]) && vtkMath::IsFinite(p[2]))
    {
      positions.push_back(p);
    }
  }
  std::sort(positions.begin(), positions.end());
  return positions;
}

// Splits `cells` into those with a point at one of `positions` and the others.
void SplitTouching(vtkCellArray* cells, vtkPoints* points,
  const std::vector<std::array<double, 3>>& positions, vtkCellArray* touching, vtkCellArray* rest)
{
  auto it = vtk::TakeSmartPointer(cells->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    it->GetCurrentCell(size, ids);
    bool touches = false;
    for (vtkIdType k = 0; k < size && !touches; ++k)
    {
      std::array<double, 3> p;
      points->GetPoint(ids[k], p.data());
      touches = vtkMath::IsFinite(p[0]) && vtkMath::IsFinite(p[1]) && vtkMath::IsFinite(p[2]) &&
        std::binary_search(positions.begin(), positions.end(), p);
    }
    (touches ? touching : rest)->InsertNextCell(size, ids);
  }
}

// The polydata of `polys` and `strips` on only the points they use.
vtkSmartPointer<vtkPolyData> Compact(vtkPoints* points, vtkCellArray* polys, vtkCellArray* strips)
{
  std::vector<vtkIdType> renumber(points->GetNumberOfPoints(), -1);
  auto used = vtkSmartPointer<vtkPoints>::New();
  used->SetDataType(points->GetDataType());
  auto compact = vtkSmartPointer<vtkPolyData>::New();
  compact->SetPoints(used);
  for (vtkCellArray* cells : { polys, strips })
  {
    vtkNew<vtkCellArray> renumbered;
    std::vector<vtkIdType> local;
    auto it = vtk::TakeSmartPointer(cells->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
    {
      vtkIdType size;
      const vtkIdType* ids;
      it->GetCurrentCell(size, ids);
      local.assign(ids, ids + size);
      for (vtkIdType& id : local)
      {
        if (renumber[id] < 0)
        {
          renumber[id] = used->InsertNextPoint(points->GetPoint(id));
        }
        id = renumber[id];
      }
      renumbered->InsertNextCell(size, local.data());
    }
    cells == polys ? compact->SetPolys(renumbered) : compact->SetStrips(renumbered);
  }
  return compact;
}
}

//------------------------------------------------------------------------------
bool vtkApertureDistributedOccluders::IsDistributed(
  vtkMultiProcessController* controller, vtkInformation* outInfo)
{
  using SDDP = vtkStreamingDemandDrivenPipeline;
  return controller && controller->GetNumberOfProcesses() > 1 && outInfo &&
    outInfo->Has(SDDP::UPDATE_NUMBER_OF_PIECES()) &&
    outInfo->Get(SDDP::UPDATE_NUMBER_OF_PIECES()) > 1;
}

//------------------------------------------------------------------------------
bool vtkApertureDistributedOccluders::GatherForPiece(vtkMultiProcessController* controller,
  vtkInformation* outInfo, vtkPolyData* input, vtkSmartPointer<vtkPolyData>& remote,
  vtkSmartPointer<vtkPolyData>& ghosts)
{
  if (!IsDistributed(controller, outInfo))
  {
    return false;
  }
  remote = Gather(controller, { input }, std::numeric_limits<double>::infinity());
  ghosts = TakeGhosts(input, remote);
  return true;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> vtkApertureDistributedOccluders::TakeGhosts(
  vtkPolyData* piece, vtkSmartPointer<vtkPolyData>& remote)
{
  if (!piece || !remote || !remote->GetPoints() || remote->GetNumberOfCells() == 0)
  {
    return nullptr;
  }
  const std::vector<std::array<double, 3>> positions = SortedPositions(piece->GetPoints());
  vtkNew<vtkCellArray> ghostPolys, ghostStrips, restPolys, restStrips;
  SplitTouching(remote->GetPolys(), remote->GetPoints(), positions, ghostPolys, restPolys);
  SplitTouching(remote->GetStrips(), remote->GetPoints(), positions, ghostStrips, restStrips);
  if (ghostPolys->GetNumberOfCells() + ghostStrips->GetNumberOfCells() == 0)
  {
    return nullptr;
  }
  auto rest = vtkSmartPointer<vtkPolyData>::New();
  rest->SetPoints(remote->GetPoints());
  rest->SetPolys(restPolys);
  rest->SetStrips(restStrips);
  vtkSmartPointer<vtkPolyData> ghosts = Compact(remote->GetPoints(), ghostPolys, ghostStrips);
  remote = rest;
  return ghosts;
}

//------------------------------------------------------------------------------
bool vtkApertureDistributedOccluders::AllSucceeded(
  vtkMultiProcessController* controller, bool ok, std::string& failed)
{
  const int ranks = controller->GetNumberOfProcesses();
  int mine = ok ? 1 : 0;
  std::vector<int> all(ranks, 0);
  controller->AllGather(&mine, all.data(), 1);
  failed.clear();
  for (int r = 0; r < ranks; ++r)
  {
    failed += all[r] ? "" : (failed.empty() ? "" : ", ") + std::to_string(r);
  }
  return failed.empty();
}

//------------------------------------------------------------------------------
std::vector<vtkPolyData*> vtkApertureDistributedOccluders::Occluders(
  vtkInformationVector* occluderInfo, vtkPolyData* remote)
{
  std::vector<vtkPolyData*> occluders;
  for (int i = 0; i < occluderInfo->GetNumberOfInformationObjects(); ++i)
  {
    if (auto* occluder = vtkPolyData::GetData(occluderInfo, i))
    {
      occluders.push_back(occluder);
    }
  }
  if (remote && remote->GetNumberOfCells() > 0)
  {
    occluders.push_back(remote);
  }
  return occluders;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> vtkApertureDistributedOccluders::Gather(
  vtkMultiProcessController* controller, const std::vector<vtkPolyData*>& local,
  double maximumDistance)
{
  // Pieces with cells outside their points are refused by the caller; they send nothing.
  std::vector<vtkPolyData*> valid;
  for (vtkPolyData* piece : local)
  {
    if (piece && piece->GetPoints() && vtkApertureCellCheck::FindBadCell(piece).empty())
    {
      valid.push_back(piece);
    }
  }
  const int ranks = controller->GetNumberOfProcesses();
  const int rank = controller->GetLocalProcessId();
  const bool all = !(maximumDistance < VTK_FLOAT_MAX);

  // Every rank's bounds, grown by the distance: the cells another rank can see.
  const vtkBoundingBox own = LocalBounds(valid);
  double bounds[6];
  own.GetBounds(bounds);
  std::vector<double> allBounds(6 * ranks);
  controller->AllGather(bounds, allBounds.data(), 6);
  std::vector<vtkBoundingBox> others;
  for (int r = 0; r < ranks && !all; ++r)
  {
    vtkBoundingBox box(&allBounds[6 * r]);
    if (r != rank && box.IsValid())
    {
      box.Inflate(maximumDistance);
      others.push_back(box);
    }
  }

  vtkNew<vtkAppendPolyData> append;
  for (vtkPolyData* piece : valid)
  {
    append->AddInputData(Surface(piece, all, others));
  }
  auto send = vtkSmartPointer<vtkPolyData>::New();
  if (!valid.empty())
  {
    append->Update();
    send->ShallowCopy(append->GetOutput());
  }
  std::vector<vtkSmartPointer<vtkDataObject>> received;
  controller->AllGather(send, received);

  vtkNew<vtkAppendPolyData> remote;
  for (int r = 0; r < static_cast<int>(received.size()); ++r)
  {
    auto* surface = vtkPolyData::SafeDownCast(received[r]);
    if (r != rank && surface && surface->GetNumberOfCells() > 0)
    {
      remote->AddInputData(surface);
    }
  }
  auto result = vtkSmartPointer<vtkPolyData>::New();
  if (remote->GetNumberOfInputConnections(0) > 0)
  {
    remote->Update();
    result->ShallowCopy(remote->GetOutput());
  }
  return result;
}
