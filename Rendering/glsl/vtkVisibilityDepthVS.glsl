//VTK::System::Dec
// vtkVisibilityScene's depth pass (the scene seen along a light direction, or by the camera):
// the scene's points placed by one matrix. Any OpenGL version VTK runs on; the passes whose
// fragment shaders need GLSL 4.30 take it in that version (vtkVisibilityScene::PointsVS430()).
in vec3 vertexMC;
uniform mat4 clipMatrix;
void main()
{
  gl_Position = clipMatrix * vec4(vertexMC, 1.0);
}
