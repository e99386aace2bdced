/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkEnvironmentMap.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkEnvironmentMap
 * @brief   a latitude-longitude HDR environment on the sphere: conventions, filtering, rotation
 *
 * Holds a latitude-longitude environment (a 2D float image, as vtkOpenEXRReader reads it: 1, 3
 * or 4 components, RGB used, grey repeated) and answers what the shading needs from it, for any
 * rotation, without touching the image again:
 *
 * - the radiance toward a world direction (Radiance());
 * - the mean radiance over each cell of a set of directions, such as a vtkLightSphere's Voronoi
 *   cells (CellRadiance()): the quadrature that Σ_j M_ij L_j w_j needs, free of aliasing;
 * - the irradiance on a surface of normal n (Irradiance(): the cosine lobe, by order-2
 *   spherical harmonics, Ramamoorthi and Hanrahan 2001);
 * - the radiance integrated over a cap, cosine-weighted around its axis (CapIrradiance()), and
 *   a table of it for shaders (NewCapTable()): the sky seen through a surface's aperture;
 * - the radiance integrated over a cap of any radius, unweighted (CapRadiance()), and its table
 *   (NewCapRadianceTable()): the sky seen through a voxel's aperture.
 *
 * Optionally the environment is first blurred on the sphere with a Gaussian of BlurAngle (the
 * paper's filtered environments): a true angular convolution, correct at the poles and across
 * the seam, not a blur of the flat image.
 *
 * **Conventions.** Image column i, row j (VTK order: row 0 at the bottom) of a W × H image has
 * its centre at u = (i + ½)/W, v = (j + ½)/H. The elevation is θ = π(v − ½): the top row looks
 * up, the bottom row down. The azimuth is φ = 2π(u − ½), measured clockwise seen from above:
 * the image's centre column looks north, its right quarter east, as a panorama turns right.
 * With up U, north N and east E the direction is cos θ (cos φ N + sin φ E) + sin θ U. UpAxis
 * picks the frame: Z (terrain; N = +y, E = +x) or Y (meshes; N = −z, E = +x), or X (N = +z,
 * E = +y). Azimuth turns the environment clockwise about U: what was north moves to the
 * azimuth given. Orientation, when set, is a further rotation applied before it.
 */

#ifndef vtkEnvironmentMap_h
#define vtkEnvironmentMap_h

#include "vtkApertureLightingCoreModule.h" // For export macro
#include "vtkObject.h"

#include <atomic> // For std::atomic
#include <mutex>  // For std::mutex
#include <vector> // For std::vector

class vtkDoubleArray;
class vtkImageData;

class VTKAPERTURELIGHTINGCORE_EXPORT vtkEnvironmentMap : public vtkObject
{
public:
  static vtkEnvironmentMap* New();
  vtkTypeMacro(vtkEnvironmentMap, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The latitude-longitude image. Any size works; 2:1 is what the conventions assume.
   */
  void SetImage(vtkImageData* image);
  vtkGetObjectMacro(Image, vtkImageData);
  ///@}

  enum Axes
  {
    X = 0,
    Y = 1,
    Z = 2
  };

  ///@{
  /**
   * World axis the environment's zenith points along. Default Z.
   */
  vtkSetClampMacro(UpAxis, int, X, Z);
  vtkGetMacro(UpAxis, int);
  void SetUpAxisToX() { this->SetUpAxis(X); }
  void SetUpAxisToY() { this->SetUpAxis(Y); }
  void SetUpAxisToZ() { this->SetUpAxis(Z); }
  ///@}

  ///@{
  /**
   * Clockwise turn of the environment about the up axis, in degrees. Default 0.
   */
  vtkSetMacro(Azimuth, double);
  vtkGetMacro(Azimuth, double);
  ///@}

  ///@{
  /**
   * A further rotation (row-major 3 × 3), applied before the azimuth. Default identity.
   */
  void SetOrientation(const double rotation[9]);
  void GetOrientation(double rotation[9]);
  ///@}

  ///@{
  /**
   * Standard deviation, in radians, of a Gaussian blur on the sphere applied to the
   * environment before anything is sampled from it. Default 0 (none).
   */
  void SetBlurAngle(double sigma);
  vtkGetMacro(BlurAngle, double);
  ///@}

  /**
   * Time of the last change to what the filtered environment depends on (the image, its data,
   * BlurAngle), but not to its rotation: tables built from it (NewCapTable()) stay valid until
   * this changes.
   */
  vtkMTimeType GetImageMTime();

  /**
   * The unit world direction of image point (u, v), and the (u, v) of a world direction.
   */
  void DirectionOf(double u, double v, double direction[3]);
  void ImagePointOf(const double direction[3], double& u, double& v);

  /**
   * Radiance (RGB) toward a world direction, bilinear in the working image (the environment
   * resampled to 256 × 128, blurred if asked).
   */
  void Radiance(const double direction[3], double rgb[3]);

  /**
   * Mean radiance (RGB, k tuples of 3 in `radiance`) over the cells of k world directions: each
   * point of the sphere belongs to the nearest direction. With a lightsphere's weights w_j,
   * Σ_j radiance_j w_j is the environment's total ∫ L dω.
   */
  void CellRadiance(vtkDoubleArray* directions, vtkDoubleArray* radiance);

  /**
   * Irradiance (RGB) on a surface of unit normal n, open to the whole environment: ∫ L
   * max(n·ω, 0) dω by order-2 spherical harmonics. A uniform environment of radiance 1 gives π.
   */
  void Irradiance(const double normal[3], double rgb[3]);

  /**
   * Radiance over the cap of angular radius r around a unit world axis, weighted by the cosine
   * to the axis: ∫_cap L (axis·ω) dω, by quadrature over the working image. An open hemisphere
   * (r = π/2) of uniform radiance 1 gives π.
   */
  void CapIrradiance(const double axis[3], double r, double rgb[3]);

  /**
   * CapIrradiance() tabulated for shaders: a float RGB image of columns × rows × radii points
   * (`CapIrradiance`). Point (i, j, k) holds the cap of radius k (π/2)/(radii − 1) around the
   * axis at image point u = (i + ½)/columns, v = (j + ½)/rows of the environment, in its own
   * frame; a shader turns a world axis into that frame with GetWorldToEnvironment() and then into
   * (u, v) by the conventions above. The caller owns the image.
   */
  vtkImageData* NewCapTable(int columns, int rows, int radii);

  /**
   * Radiance over the cap of angular radius r (0 to π) around a unit world axis, unweighted:
   * ∫_cap L dω, by quadrature over the working image. The whole sphere of uniform radiance 1
   * gives 4π.
   */
  void CapRadiance(const double axis[3], double r, double rgb[3]);

  /**
   * CapRadiance() tabulated for shaders as NewCapTable() tabulates CapIrradiance(), with radii
   * from 0 to π: point (i, j, k) holds the cap of radius k π/(radii − 1) (`CapRadiance`).
   */
  vtkImageData* NewCapRadianceTable(int columns, int rows, int radii);

  /**
   * The environment over wedges of another frame's sky, tabled for horizons
   * (vtkHorizonLighting::EnvironmentSkyTransfer()): a float RGB image of (azimuths + 1) ×
   * elevations × 3 points (`WedgeIrradiance`). Point (i, j, a) holds ∫ L(ω) ω_a dω over the
   * directions of that frame with azimuth below φ_i = 2πi/azimuths (from its +x toward +y) and
   * elevation above e_j = −π/2 + πj/(elevations − 1) (above its xy plane), ω_a the direction's
   * component a in the frame; the wedge between two azimuths is the difference of two columns.
   * frameToWorld (row-major 3 × 3, a rotation with a uniform scale allowed) takes the frame's
   * directions to world ones. Quadrature over the working image, each pixel split 4 × 4.
   * The caller owns the image.
   */
  vtkImageData* NewWedgeTable(int azimuths, int elevations, const double frameToWorld[9]);

  /**
   * The environment blurred for cells of a visibility mask (vtkVisibilityMask::
   * EnvironmentSkyTransfer()): a float RGB image of columns × rows points (`MeanRadiance`) whose
   * point (i, j) holds the mean radiance over the cap of angular radius r around the axis at
   * image point u = (i + ½)/columns, v = (j + ½)/rows, in the environment's own frame:
   * CapRadiance() / (2π(1 − cos r)), the axis's own radiance for caps smaller than a pixel. The
   * caller owns the image.
   */
  vtkImageData* NewMeanRadianceTable(int columns, int rows, double r);

  /**
   * A table of RGB floats of columns × rows points laid out as the environment's image (point
   * (i, j) at u = (i + ½)/columns, v = (j + ½)/rows) sampled toward a unit direction of the
   * environment's own frame as a shader samples its texture: bilinear, around the seam in
   * azimuth, clamped at the poles.
   */
  static void SampleTable(
    const float* table, int columns, int rows, const double local[3], double rgb[3]);

  /**
   * The matrix (row-major 3 × 3) taking a world direction into the environment's own frame (x
   * north, y east, z up, unrotated), where (u, v) follow from the conventions:
   * φ = atan2(y, x), θ = asin(z).
   */
  void GetWorldToEnvironment(double matrix[9]);

protected:
  vtkEnvironmentMap();
  ~vtkEnvironmentMap() override;

  // Resamples and blurs the image into the working image when the image or BlurAngle changed
  // (not the rotation: the working image is in the environment's own frame). Safe to call from
  // several threads at once: the queries below are, as long as nobody changes the image meanwhile.
  void Update();
  void Rebuild();
  // Rebuild()'s steps: the image resampled to the working grid (false without an image), the
  // blur, and the spherical harmonics.
  bool Resample();
  void Blur();
  void ProjectHarmonics();
  // NewWedgeTable()'s quadrature: the working image's samples binned by azimuth and elevation
  // in the frame that toFrame takes world directions to, as 3 axes × RGB a bin.
  std::vector<double> WedgeBins(int azimuths, int elevations, const double toFrame[3][3]);

  vtkImageData* Image = nullptr;
  int UpAxis = Z;
  double Azimuth = 0.0;
  double Orientation[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  double BlurAngle = 0.0;

private:
  vtkEnvironmentMap(const vtkEnvironmentMap&) = delete;
  void operator=(const vtkEnvironmentMap&) = delete;

  // Unit direction of environment pixel (i, j) of a w x h grid, in the environment's frame
  // (x north, y east, z up); and back.
  static void Local(double u, double v, double d[3]);
  static void LocalToImagePoint(const double d[3], double& u, double& v);
  // World <-> environment frame, with the rotation and the up axis.
  void ToWorld(const double local[3], double world[3]);
  void ToLocal(const double world[3], double local[3]);
  // The radiance over a cap, weighted by the cosine to its axis (hemispheres only) or not; and
  // tabulated over axes and radii up to pi/2 (weighted) or pi.
  void CapSum(const double axis[3], double r, bool cosine, double rgb[3]);
  vtkImageData* NewTable(int columns, int rows, int radii, bool cosine);

  // The working image: 256 x 128 RGB, solid angles per row, the direction of each pixel (in the
  // environment's frame), and the SH-9 irradiance coefficients.
  std::vector<float> Working;
  std::vector<double> RowSolidAngle;
  std::vector<double> PixelDirections;
  double SH[9][3];
  vtkTimeStamp FilterTime;                    // the image or the blur set
  std::atomic<vtkMTimeType> WorkingTime{ 0 }; // 0 until the first update
  std::mutex UpdateMutex;
};

#endif
