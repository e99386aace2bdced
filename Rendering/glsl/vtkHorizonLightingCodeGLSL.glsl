// ApertureLighting: vtkHorizonLighting::DecodeAngle() for shaders, on its own so that vertex
// shaders can decode horizons without the rest of the twin.

// A horizon from its 8-bit code read as a normalised value v = code / 255:
// t = 2v - 1, h = (pi/2) t |t|.
float horizonLightingDecode(float v)
{
  float t = 2.0 * v - 1.0;
  return 1.57079632679490 * t * abs(t);
}
