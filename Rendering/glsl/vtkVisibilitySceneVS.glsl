#version 430 core
// vtkVisibilityScene: the scene's points placed by one matrix, for the passes that need GLSL
// 4.30 fragment shaders (DepthCompare's paired depth pass and the camera pass).
in vec3 vertexMC;
uniform mat4 clipMatrix;
void main()
{
  gl_Position = clipMatrix * vec4(vertexMC, 1.0);
}
