//VTK::System::Dec
// vtkVisibilityRenderer's depth pass: depth only, nothing to shade.
void main()
{
}
