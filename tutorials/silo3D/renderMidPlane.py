"""Pictures of the silo's mid-plane (y = 0) at several times, rendered
headless by ParaView (run by Allrun: xvfb-run -a pvbatch renderMidPlane.py).

Writes, side by side at up to six written times from the first to the last
(equally spaced; ParaView's OpenFOAM reader of 5.11 does not list the initial
time 0, whatever SkipZeroTime says), the solids fraction n.fine + n.coarse into
results/midPlane_solidsFraction.png and the coarse species' solids fraction
n.coarse into results/midPlane_nCoarse.png, one colour scale per picture.
"""

import os

from paraview.simple import (
    Calculator, ColorBy, CreateView, ForceTime, GetColorTransferFunction,
    GetScalarBar, OpenFOAMReader, SaveScreenshot, Show, Slice, Text,
    Transform)

case = os.getcwd()
reader = OpenFOAMReader(FileName=os.path.join(case, "silo3D.foam"))
reader.MeshRegions = ["internalMesh"]
reader.CellArrays = ["n.fine", "n.coarse"]
reader.UpdatePipelineInformation()
allTimes = list(reader.TimestepValues)
if not allTimes:
    raise SystemExit("renderMidPlane: no time directories in " + case)
nPics = min(6, len(allTimes))
times = [allTimes[round(k*(len(allTimes) - 1)/max(nPics - 1, 1))]
         for k in range(nPics)]

midPlane = Slice(Input=reader)
midPlane.SliceType = "Plane"
midPlane.SliceType.Origin = [0, 0, 0.3]
midPlane.SliceType.Normal = [0, 1, 0]
midPlane.Triangulatetheslice = 0
solids = Calculator(Input=midPlane)
solids.AttributeType = "Cell Data"
solids.ResultArrayName = "solidsFraction"
solids.Function = '"n.fine" + "n.coarse"'

reader.UpdatePipeline(times[0])
bounds = reader.GetDataInformation().GetBounds()
width = 1.25*(bounds[1] - bounds[0])
os.makedirs(os.path.join(case, "results"), exist_ok=True)

# Pixels per metre, the view's size and the camera: the pictures side by
# side, a margin for the colour bar on the right
scale = 0.42                       # half the visible height [m]
height = 760
pxPerM = height/(2*scale)
span = (nPics - 1)*width + (bounds[1] - bounds[0])
barMargin = 170
size = [int(span*pxPerM + 40 + barMargin), height]
left = bounds[0] - 20/pxPerM       # the view's left edge [m]
centreX = left + 0.5*size[0]/pxPerM

for field, title, upper, png in (
        ("solidsFraction", "solids fraction", 0.6, "midPlane_solidsFraction.png"),
        ("n.coarse", "n.coarse", 0.3, "midPlane_nCoarse.png")):
    view = CreateView("RenderView")
    view.ViewSize = size
    view.UseColorPaletteForBackground = 0
    view.Background = [1, 1, 1]
    view.OrientationAxesVisibility = 0
    lut = GetColorTransferFunction(field)
    lut.ApplyPreset("Viridis (matplotlib)", True)
    lut.AutomaticRescaleRangeMode = "Never"
    lut.RescaleTransferFunction(0.0, upper)
    for k, t in enumerate(times):
        atTime = ForceTime(Input=solids)
        atTime.ForcedTime = t
        atTime.IgnorePipelineTime = 1
        placed = Transform(Input=atTime)
        placed.Transform.Translate = [k*width, 0, 0]
        display = Show(placed, view)
        ColorBy(display, ("CELLS", field))
        display.LookupTable = lut
        display.Ambient = 1.0      # flat colours, no shading
        display.Diffuse = 0.0
        label = Text(Text="t = %g s" % t)
        labelDisplay = Show(label, view)
        labelDisplay.WindowLocation = "Any Location"
        labelDisplay.Position = [((k*width - 0.05) - left)*pxPerM/size[0], 0.015]
        labelDisplay.Color = [0, 0, 0]
        labelDisplay.FontSize = 14
    bar = GetScalarBar(lut, view)
    bar.Title = title
    bar.ComponentTitle = ""
    bar.TitleColor = [0, 0, 0]
    bar.LabelColor = [0, 0, 0]
    bar.WindowLocation = "Any Location"
    bar.Position = [1 - 0.8*barMargin/size[0], 0.25]
    bar.ScalarBarLength = 0.5
    bar.Visibility = 1
    lut.RescaleTransferFunction(0.0, upper)   # ColorBy rescaled it
    view.CameraParallelProjection = 1
    view.CameraPosition = [centreX, -2.0, 0.36]
    view.CameraFocalPoint = [centreX, 0, 0.36]
    view.CameraViewUp = [0, 0, 1]
    view.CameraParallelScale = scale
    out = os.path.join(case, "results", png)
    SaveScreenshot(out, view, ImageResolution=size)
    print("renderMidPlane: %s (%s at t = %s s)"
          % (out, title, ", ".join("%g" % t for t in times)))
