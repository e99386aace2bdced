//VTK::System::Dec
// vtkVisibilityScene's depth pass: depth only, nothing to shade.
void main()
{
}
