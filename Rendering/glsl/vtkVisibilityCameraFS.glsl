#version 430 core
// vtkVisibilityCameraPass (vertex filtering): candidate triangles that survive the
// early depth test against the scene mark their bit.
layout(early_fragment_tests) in;
layout(std430, binding = 0) buffer Seen { uint seen[]; };
void main()
{
  uint bit = 1u << uint(gl_PrimitiveID % 32);
  if ((seen[gl_PrimitiveID / 32] & bit) == 0u)
  {
    atomicOr(seen[gl_PrimitiveID / 32], bit);
  }
}
