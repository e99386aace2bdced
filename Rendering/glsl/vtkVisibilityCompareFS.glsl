#version 430 core
// vtkVisibilityMatrixPasses' DepthCompare test rasterises nothing; a program needs a fragment
// shader.
out vec4 color;
void main()
{
  color = vec4(1.0);
}
