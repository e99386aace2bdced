#version 430 core
// vtkVisibilityMatrixPasses' DepthCompare test, in a vertex shader (nothing is rasterised): the
// receiver's window depth against the texel it falls on, nearer than the nearest surface for the
// direction (the occlusion-query pass's GL_LESS test), farther than the farthest for its opposite,
// seen from the same side (the opposite direction's orthographic view is this one mirrored, on
// the same texel centres). Visible receivers set their bit in the direction's slot.
in vec3 vertexMC;
uniform mat4 lightMatrix;
uniform sampler2D nearestMap;
uniform sampler2D farthestMap;
uniform int resolution;
uniform int slot;
uniform int opposite;
uniform int words;
layout(std430, binding = 0) buffer Visibility { uint bits[]; };
void main()
{
  vec4 clip = lightMatrix * vec4(vertexMC, 1.0);
  vec3 ndc = clip.xyz / clip.w;
  ivec2 texel = ivec2(floor((ndc.xy * 0.5 + 0.5) * float(resolution)));
  float depth = ndc.z * 0.5 + 0.5;
  uint bit = 1u << uint(gl_VertexID % 32);
  int word = gl_VertexID / 32;
  if (all(greaterThanEqual(texel, ivec2(0))) && all(lessThan(texel, ivec2(resolution))))
  {
    if (depth < texelFetch(nearestMap, texel, 0).r)
    {
      atomicOr(bits[slot * words + word], bit);
    }
    if (opposite >= 0 && depth > texelFetch(farthestMap, texel, 0).r)
    {
      atomicOr(bits[opposite * words + word], bit);
    }
  }
  gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
}
