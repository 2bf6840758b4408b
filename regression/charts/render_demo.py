# Renders the demo's results with ParaView itself, as proof that railfe's Exodus files open there
# and as the picture in docs/user-guide.md. Needs Debian's paraview and python3-paraview (not
# installed by the project: ParaView is a viewer, not a dependency) and an X display or xvfb-run:
#   PYTHONPATH=/usr/lib/python3/dist-packages xvfb-run -a pvbatch regression/charts/render_demo.py \
#       demo_results/wheel_load.exo docs/img/demo_paraview.png
import sys

from paraview.simple import (ColorBy, CreateView, ExodusIIReader, GetColorTransferFunction,
                             MergeBlocks, Render, SaveScreenshot, Show, WarpByVector, servermanager)

reader = ExodusIIReader(FileName=sys.argv[1])
reader.UpdatePipelineInformation()
reader.PointVariables = reader.PointVariables.Available
reader.ElementVariables = reader.ElementVariables.Available
merged = MergeBlocks(Input=reader)
merged.UpdatePipeline()
data = servermanager.Fetch(merged)
print("ParaView read", data.GetNumberOfPoints(), "points,", data.GetNumberOfCells(), "cells;",
      "point variables", list(reader.PointVariables.Available), "element variables",
      list(reader.ElementVariables.Available))
# ParaView joins displacement_x/_y/_z into the vector "displacement_".
warped = WarpByVector(Input=merged, Vectors=["POINTS", "displacement_"], ScaleFactor=200)
view = CreateView("RenderView")
view.ViewSize = [900, 500]
shown = Show(warped, view)
shown.SetRepresentationType("Surface With Edges")
shown.EdgeColor = [0.2, 0.2, 0.2]
ColorBy(shown, ("CELLS", "von_mises"))
colours = GetColorTransferFunction("von_mises")
colours.UseLogScale = 1
colours.RescaleTransferFunction(1e5, 4e8)
shown.SetScalarBarVisibility(view, True)
view.CameraPosition = [-0.35, -0.45, 0.35]
view.CameraFocalPoint = [0.12, 0.036, 0.08]
view.CameraViewUp = [0, 0, 1]
Render(view)
SaveScreenshot(sys.argv[2], view)
