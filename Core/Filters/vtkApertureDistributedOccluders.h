/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureDistributedOccluders.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkApertureDistributedOccluders
 * @brief   the other ranks' surfaces, for a filter run on one piece of distributed data (private)
 *
 * Distributed over MPI, each rank holds one piece of a surface, but shadows come from all of
 * them. Gather() sends this rank's polygons and triangle strips (points and cells, no arrays) to
 * every rank and returns the other ranks' as one vtkPolyData, to be added as occluders: a
 * distributed run then casts its rays against the same geometry as a serial one. With a finite
 * maximum distance, only the cells within that distance of some other rank's bounds travel.
 *
 * Gather() is collective: every rank of the controller must call it, one with an empty piece or
 * with a piece it is about to refuse as well (such a piece sends nothing).
 */

#ifndef vtkApertureDistributedOccluders_h
#define vtkApertureDistributedOccluders_h

#include "vtkApertureLightingCoreModule.h" // For export macro
#include "vtkSmartPointer.h"               // For vtkSmartPointer

#include <string> // For std::string
#include <vector> // For std::vector

class vtkInformation;
class vtkInformationVector;
class vtkMultiProcessController;
class vtkPolyData;

class VTKAPERTURELIGHTINGCORE_EXPORT vtkApertureDistributedOccluders
{
public:
  /**
   * Whether a request is for one of several pieces under a controller of several processes:
   * the case in which a filter gathers the other pieces' surfaces.
   */
  static bool IsDistributed(vtkMultiProcessController* controller, vtkInformation* outInfo);

  /**
   * The other ranks' surfaces (collective; empty when they have none). `local` are this rank's
   * pieces; cells beyond `maximumDistance` of every other rank's bounds stay home.
   */
  static vtkSmartPointer<vtkPolyData> Gather(vtkMultiProcessController* controller,
    const std::vector<vtkPolyData*>& local, double maximumDistance);

  /**
   * For a filter of one surface: when the request is distributed, the other ranks' whole
   * surfaces (collective), the cells around the input's border into `ghosts` (TakeGhosts()) and
   * the others into `remote`, and true.
   */
  static bool GatherForPiece(vtkMultiProcessController* controller, vtkInformation* outInfo,
    vtkPolyData* input, vtkSmartPointer<vtkPolyData>& remote, vtkSmartPointer<vtkPolyData>& ghosts);

  /**
   * Moves the cells of `remote` that touch a point of `piece` (at the same position) into the
   * returned polydata, on their own points: the ring of the other pieces around this piece's
   * border, which belongs to its points' surface (their normals, creases, ray offsets and own
   * triangles) rather than to the occluders. `remote` keeps the other cells. Returns nullptr when
   * no cell touches the piece.
   */
  static vtkSmartPointer<vtkPolyData> TakeGhosts(
    vtkPolyData* piece, vtkSmartPointer<vtkPolyData>& remote);

  /**
   * After a distributed filter's work (collective): whether every rank's `ok` is true; when not,
   * the ranks that failed, in `failed` ("1, 3").
   */
  static bool AllSucceeded(vtkMultiProcessController* controller, bool ok, std::string& failed);

  /**
   * A filter's occluders: the vtkPolyData on its occluder port, and `remote` when it has cells.
   */
  static std::vector<vtkPolyData*> Occluders(
    vtkInformationVector* occluderInfo, vtkPolyData* remote);
};

#endif
