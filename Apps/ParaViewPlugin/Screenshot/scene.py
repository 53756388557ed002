# The scene of take-screenshot, run by ParaView's GUI (paraview --script).
from paraview.simple import *
cube = Clean(Input=Box())
RenameSource("Cube", cube)
cc = SubDCatmullClark(Input=cube)
cc.NumberOfSubdivisions = 3
cc.ComputeCurvature = 1
cc.ComputeLimitNormals = 1
view = GetActiveViewOrCreate("RenderView")
d = Show(cc, view)
ColorBy(d, ("POINTS", "Mean_Curvature"))
d.RescaleTransferFunctionToDataRange(True)
d.SetScalarBarVisibility(view, True)
cage = Show(cube, view)
cage.SetRepresentationType("Wireframe")
cage.AmbientColor = [1, 1, 1]
cage.DiffuseColor = [1, 1, 1]
cage.LineWidth = 2
view.CameraPosition = [2.2, 1.6, 2.6]
view.CameraFocalPoint = [0, 0, 0]
view.CameraViewUp = [0, 1, 0]
SetActiveSource(cc)
Render()
