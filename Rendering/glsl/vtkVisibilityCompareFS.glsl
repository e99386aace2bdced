#version 430 core
// vtkVisibilityRenderer's DepthCompare test rasterises nothing; a program needs a fragment shader.
out vec4 color;
void main()
{
  color = vec4(1.0);
}
