/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureCellCheck.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkApertureCellCheck.h"

#include "vtkCellArray.h"
#include "vtkIdTypeArray.h"
#include "vtkPolyData.h"
#include "vtkUnstructuredGrid.h"

#include <sstream>

namespace
{
// Walks raw offsets and connectivity: nothing here trusts either.
template <typename Value>
std::string Walk(const Value* offsets, vtkIdType numberOfOffsets, const Value* connectivity,
  vtkIdType numberOfIds, vtkIdType numberOfPoints, const char* kind, vtkIdType firstCellId)
{
  std::ostringstream what;
  if (numberOfOffsets == 0)
  {
    return numberOfIds == 0 ? std::string() : std::string("the ") + kind + " cells are damaged";
  }
  if (offsets[0] != 0 || offsets[numberOfOffsets - 1] != numberOfIds)
  {
    what << "the " << kind << " cells are damaged (their offsets do not span their " << numberOfIds
         << " point ids)";
    return what.str();
  }
  for (vtkIdType cell = 0; cell + 1 < numberOfOffsets; ++cell)
  {
    if (offsets[cell + 1] < offsets[cell])
    {
      what << kind << " " << cell << " (cell " << firstCellId + cell
           << ") is damaged (its offset runs backwards)";
      return what.str();
    }
    for (Value k = offsets[cell]; k < offsets[cell + 1]; ++k)
    {
      const Value id = connectivity[k];
      if (id < 0 || static_cast<vtkIdType>(id) >= numberOfPoints)
      {
        what << kind << " " << cell << " (cell " << firstCellId + cell << ") uses point id "
             << static_cast<long long>(id) << ", but there "
             << (numberOfPoints == 1 ? "is 1 point"
                                     : "are " + std::to_string(numberOfPoints) + " points");
        return what.str();
      }
    }
  }
  return std::string();
}
}

//------------------------------------------------------------------------------
std::string vtkApertureCellCheck::FindBadCell(
  vtkCellArray* cells, vtkIdType numberOfPoints, const char* kind, vtkIdType firstCellId)
{
  if (!cells)
  {
    return std::string();
  }
  if (cells->IsStorage64Bit())
  {
    auto* offsets = cells->GetOffsetsArray64();
    auto* connectivity = cells->GetConnectivityArray64();
    return Walk(offsets->GetPointer(0), offsets->GetNumberOfValues(), connectivity->GetPointer(0),
      connectivity->GetNumberOfValues(), numberOfPoints, kind, firstCellId);
  }
  auto* offsets = cells->GetOffsetsArray32();
  auto* connectivity = cells->GetConnectivityArray32();
  return Walk(offsets->GetPointer(0), offsets->GetNumberOfValues(), connectivity->GetPointer(0),
    connectivity->GetNumberOfValues(), numberOfPoints, kind, firstCellId);
}

//------------------------------------------------------------------------------
std::string vtkApertureCellCheck::FindBadCell(vtkPolyData* input)
{
  const vtkIdType n = input->GetNumberOfPoints();
  vtkCellArray* const arrays[] = { input->GetVerts(), input->GetLines(), input->GetPolys(),
    input->GetStrips() };
  const char* const kinds[] = { "vertex", "line", "polygon", "strip" };
  vtkIdType first = 0;
  for (int k = 0; k < 4; ++k)
  {
    const std::string problem = FindBadCell(arrays[k], n, kinds[k], first);
    if (!problem.empty())
    {
      return problem;
    }
    first += arrays[k] ? arrays[k]->GetNumberOfCells() : 0;
  }
  return std::string();
}

//------------------------------------------------------------------------------
std::string vtkApertureCellCheck::FindBadCell(vtkUnstructuredGrid* input)
{
  const vtkIdType n = input->GetNumberOfPoints();
  std::string problem = FindBadCell(input->GetCells(), n, "cell", 0);
  vtkIdTypeArray* faces = input->GetFaces();
  vtkIdTypeArray* locations = input->GetFaceLocations();
  if (!problem.empty() || !faces || !locations)
  {
    return problem;
  }
  // Polyhedra: at each cell's location, a face count, then each face's point count and ids.
  const vtkIdType size = faces->GetNumberOfValues();
  for (vtkIdType cell = 0; cell < locations->GetNumberOfValues(); ++cell)
  {
    vtkIdType at = locations->GetValue(cell);
    if (at < 0)
    {
      continue;
    }
    const vtkIdType count = at < size ? faces->GetValue(at++) : -1;
    for (vtkIdType face = 0; face < count && problem.empty(); ++face)
    {
      const vtkIdType points = at < size ? faces->GetValue(at++) : -1;
      if (points < 0 || points > size - at)
      {
        problem = "the faces of polyhedron " + std::to_string(cell) + " are damaged";
      }
      for (vtkIdType k = 0; k < points && problem.empty(); ++k, ++at)
      {
        const vtkIdType id = faces->GetValue(at);
        if (id < 0 || id >= n)
        {
          problem = "polyhedron " + std::to_string(cell) + " uses point id " + std::to_string(id) +
            ", but there are " + std::to_string(n) + " points";
        }
      }
    }
    if (count < 0 && problem.empty())
    {
      problem = "the faces of polyhedron " + std::to_string(cell) + " are damaged";
    }
    if (!problem.empty())
    {
      return problem;
    }
  }
  return problem;
}
