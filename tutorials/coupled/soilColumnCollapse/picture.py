#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     tutorials/coupled/soilColumnCollapse/picture.py
#
# Description
#     The paper's Fig. 5 through ParaView's OpenFOAM reader: the water's
#     velocity magnitude as colour (one colour range for all panels) and the
#     soil's material points on top, at the requested times (default 0, 3 and
#     6 s; the nearest written time is taken, each once). Run with pvpython
#     under a virtual X server:
#
#         xvfb-run -a pvpython picture.py [--case DIR] [--times 0 3 6]
#             [--png soilColumnCollapse.png] [--width 900]
#
#     Writes one PNG per time (<png stem>_t<time>.png) and the panels stacked
#     top to bottom in <png>. A 3D case is shown as the slice through the
#     middle of the tank with all points projected on it. Prints the times,
#     the colour range and the files; exits 1 if nothing could be rendered.
#------------------------------------------------------------------------------

import argparse
import os
import sys


def parseArgs(argv):
    p = argparse.ArgumentParser(prog='picture.py')
    p.add_argument('--case', default='.')
    p.add_argument('--times', type=float, nargs='+', default=[0.0, 3.0, 6.0])
    p.add_argument('--png', default='soilColumnCollapse.png')
    p.add_argument('--width', type=int, default=900)
    p.add_argument('--strainMax', type=float, default=2.0,
                   help='top of the soil plastic strain colour scale')
    return p.parse_args(argv)


def fetchBlocks(reader, time):
    """{'/internalMesh': dataset, '/lagrangian/materialPoints': dataset}"""
    from paraview import servermanager
    reader.UpdatePipeline(time)
    found = {}

    def walk(ds, prefix):
        if ds is None:
            return
        if ds.IsA('vtkMultiBlockDataSet'):
            for i in range(ds.GetNumberOfBlocks()):
                name = None
                if ds.HasMetaData(i):
                    name = ds.GetMetaData(i).Get(ds.NAME())
                walk(ds.GetBlock(i), prefix + '/' + (name or 'block%d' % i))
        else:
            found[prefix] = ds
    walk(servermanager.Fetch(reader), '')
    return found


def speedRange(mesh):
    import numpy
    from vtk.util.numpy_support import vtk_to_numpy
    array = mesh.GetCellData().GetArray('U')
    if array is None:
        return None
    u = vtk_to_numpy(array).reshape(-1, 3)
    s = numpy.sqrt((u**2).sum(axis=1))
    return float(s.max()) if numpy.isfinite(s).all() else None


def stackPanels(panels, png):
    """The PNG files panels stacked top to bottom into png (VTK's image
    origin is the bottom)"""
    import vtk
    append = vtk.vtkImageAppend()
    append.SetAppendAxis(1)
    for name in reversed(panels):
        r = vtk.vtkPNGReader()
        r.SetFileName(name)
        r.Update()
        image = vtk.vtkImageData()
        image.DeepCopy(r.GetOutput())
        append.AddInputData(image)
    append.Update()
    writer = vtk.vtkPNGWriter()
    writer.SetFileName(png)
    writer.SetInputData(append.GetOutput())
    writer.Write()


def timeName(t):
    return ('%.6g' % t).replace('.', 'p')


def openCase(case):
    """ParaView's OpenFOAM reader on the reconstructed case (a case.foam
    made if missing): the mesh's cell data and the soil's cloud if any"""
    import paraview.simple as pv
    foamFile = os.path.join(os.path.abspath(case), 'case.foam')
    if not os.path.exists(foamFile):
        open(foamFile, 'a').close()
    reader = pv.OpenFOAMReader(FileName=foamFile)
    reader.CaseType = 'Reconstructed Case'
    reader.SkipZeroTime = 0
    reader.Createcelltopointfiltereddata = 0
    reader.Adddimensionalunitstoarraynames = 0
    reader.Refresh()
    reader.UpdatePipelineInformation()
    available = list(reader.GetProperty('MeshRegions').Available)
    cloud = 'lagrangian/materialPoints'
    reader.MeshRegions = ['internalMesh'] \
        + ([cloud] if cloud in available else [])
    return reader


def styleBar(bar, title, position, orientation='Vertical', length=0.6):
    """A colour bar's look: black text, three significant digits."""
    for key, value in dict(
            Title=title, ComponentTitle='', TitleColor=[0.0, 0.0, 0.0],
            LabelColor=[0.0, 0.0, 0.0], RangeLabelFormat='%-.3g',
            Orientation=orientation, WindowLocation='Any Location',
            Position=position, ScalarBarLength=length).items():
        setattr(bar, key, value)


def colourBy(pv, display, view, association, field, presets, lo, hi,
             title, orientation, position, length):
    """Colour a display by a field with a fixed range and its bar."""
    pv.ColorBy(display, (association,) + tuple(field))
    lut = pv.GetColorTransferFunction(field[0])
    for preset in presets:
        try:
            lut.ApplyPreset(preset, True)
            break
        except Exception:
            continue
    lut.RescaleTransferFunction(lo, hi)
    lut.AutomaticRescaleRangeMode = 'Never'
    display.SetScalarBarVisibility(view, True)
    bar = pv.GetScalarBar(lut, view)
    styleBar(bar, title, position, orientation, length)
    return lut, bar


def savePanel(pv, view, stem, t, width, height, prog):
    """Render the view at time t into <stem>_t<t>.png; its name."""
    pv.Render(view)
    name = '%s_t%s.png' % (stem, timeName(t))
    pv.SaveScreenshot(name, view, ImageResolution=[width, height])
    print('%s: %s' % (prog, name))
    return name


def midSlice(pv, source, centre):
    """The plane z = centre's through a 3D case."""
    cut = pv.Slice(Input=source)
    cut.SliceType = 'Plane'
    cut.SliceType.Origin = centre
    cut.SliceType.Normal = [0.0, 0.0, 1.0]
    return cut


def main(argv):
    args = parseArgs(argv)
    import paraview.simple as pv
    caseDir = os.path.abspath(args.case)
    cloud = 'lagrangian/materialPoints'
    reader = openCase(caseDir)
    # A free surface (the freeSurface effect): only the water's cells
    # drawn, where alpha.water >= 0.5 (the air white)
    import re
    with open(os.path.join(caseDir, 'constant', 'physicsProperties')) as f:
        scene = re.search(r'^\s*effects\s*\(([^)]*)\)', f.read(), re.M)
    freeSurface = bool(scene) and 'freeSurface' in scene.group(1).split()
    reader.CellArrays = ['U', 'soilFraction'] + (['alpha.water'] if freeSurface else [])
    reader.LagrangianArrays = ['plasticStrain']

    times = reader.TimestepValues
    if isinstance(times, (int, float)):
        times = [times]
    times = sorted(float(t) for t in (times or []))
    if not times:
        print('picture.py: no time directories in %s' % caseDir)
        return 1
    chosen = []
    for t in args.times:
        near = min(times, key=lambda s: abs(s - t))
        if near not in chosen:
            chosen.append(near)

    # One colour range for all panels: the largest water speed shown
    uMax = 0.0
    phiMax = 0.0
    bounds = None
    for t in chosen:
        blocks = fetchBlocks(reader, t)
        mesh = blocks.get('/internalMesh')
        if mesh is None:
            print('picture.py: no internal mesh at t = %g' % t)
            return 1
        bounds = mesh.GetBounds()
        nCells = mesh.GetNumberOfCells()
        s = speedRange(mesh)
        if s is None:
            print('picture.py: no finite U at t = %g' % t)
            return 1
        uMax = max(uMax, s)
        phi = mesh.GetCellData().GetArray('soilFraction')
        if phi is not None:
            phiMax = max(phiMax, phi.GetRange()[1])
    if uMax <= 0:
        uMax = 1.0
    print('picture.py: times %s, water speed 0 to %.4g m/s'
          % (' '.join('%g' % t for t in chosen), uMax))

    size = [bounds[1] - bounds[0], bounds[3] - bounds[2],
            bounds[5] - bounds[4]]
    centre = [(bounds[2*i] + bounds[2*i + 1])/2 for i in range(3)]
    flat = size[2] < 0.05*max(size)
    dx = (size[0]*size[1]*size[2]/max(nCells, 1))**(1.0/3.0)
    width = args.width
    height = int(round(0.82*width*size[1]/size[0] + 70))
    ppm = 0.82*width/size[0]        # pixels per metre

    view = pv.CreateView('RenderView')
    view.ViewSize = [width, height]
    view.OrientationAxesVisibility = 0
    try:
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    view.Background = [1.0, 1.0, 1.0]
    black = [0.0, 0.0, 0.0]

    water = pv.ExtractBlock(Input=reader, Selectors=['/Root/internalMesh'])
    if not flat:
        water = midSlice(pv, water, centre)
    if freeSurface:
        water = pv.Threshold(Input=water)
        water.Scalars = ['CELLS', 'alpha.water']
        try:
            water.LowerThreshold = 0.5
            water.UpperThreshold = 2.0
            water.ThresholdMethod = 'Between'
        except AttributeError:
            water.ThresholdRange = [0.5, 2.0]
    waterDisplay = pv.Show(water, view)
    waterDisplay.Representation = 'Surface'
    # The tank framed (its outline: with a free surface the air is white)
    tank = pv.ExtractBlock(Input=reader, Selectors=['/Root/internalMesh'])
    if not flat:
        tank = midSlice(pv, tank, centre)
    frame = pv.Show(pv.Outline(Input=tank), view)
    frame.ColorArrayName = ['POINTS', '']
    frame.AmbientColor = frame.DiffuseColor = black
    frame.LineWidth = 1.5
    frame.Position = [0.0, 0.0, 1.02*size[2] + 0.02]
    colourBy(pv, waterDisplay, view, 'CELLS', ('U', 'Magnitude'),
             ('Turbo', 'Jet'), 0.0, uMax, 'water |U| [m/s]', 'Vertical',
             [0.89, 0.15], 0.7)

    strainBar = None
    if cloud in reader.MeshRegions:
        # The soil as a body, not as its points: where its solid fraction
        # is half the largest or more (soilFraction, the nodal fraction the
        # solver writes, interpolated to the mesh's points and clipped: a
        # smooth outline), coloured by the points' accumulated
        # plastic strain (a Gaussian kernel of 1.5 cells over the points).
        # Drawn as points the soil showed stripes: arcs of points with
        # empty strips between them, where shearing thinned the rows; the
        # cells there all hold points (1 of 745 cells of the body empty at
        # 6 s, 3 to 5 points in most; the README's "Stripes"): the
        # rendering, not a fracture
        soilMesh = pv.ExtractBlock(Input=reader,
                                   Selectors=['/Root/internalMesh'])
        if not flat:
            soilMesh = midSlice(pv, soilMesh, centre)
        body = pv.Clip(Input=pv.CellDatatoPointData(Input=soilMesh))
        body.ClipType = 'Scalar'
        body.Scalars = ['POINTS', 'soilFraction']
        body.Value = 0.5*phiMax if phiMax > 0 else 0.3
        body.Invert = 0
        cloudPoints = pv.MergeBlocks(Input=pv.ExtractBlock(
            Input=reader, Selectors=['/Root/' + cloud]))
        # (Input: the points that carry the data; Source: where it goes)
        strain = pv.PointDatasetInterpolator(Input=cloudPoints,
                                             Source=pv.MergeBlocks(Input=body))
        strain.Kernel = 'GaussianKernel'
        strain.Kernel.Radius = 1.5*dx
        strain.NullPointsStrategy = 'Closest Point'
        bodyDisplay = pv.Show(strain, view)
        bodyDisplay.Representation = 'Surface'
        strainLut, strainBar = colourBy(
            pv, bodyDisplay, view, 'POINTS', ('plasticStrain',),
            ('Inferno (matplotlib)',), 0.0, args.strainMax,
            'soil plastic strain [-]', 'Horizontal', [0.55, 0.74], 0.3)
        if not freeSurface:
            # (over the water's dark colours: the bar's text in white)
            strainBar.TitleColor = strainBar.LabelColor = [1.0, 1.0, 1.0]
        # In front of the water (the camera looks along -z)
        bodyDisplay.Position = [0.0, 0.0, 1.01*size[2] + 0.01]
        # Where no soil fraction was written (the start, seeded by
        # setMaterialPoints): the points, in the same colours, at about
        # their spacing when seeded
        pointsDisplay = pv.Show(cloudPoints, view)
        pointsDisplay.Representation = 'Points'
        pv.ColorBy(pointsDisplay, ('POINTS', 'plasticStrain'))
        pointsDisplay.PointSize = max(2.0, 0.5*ppm*dx)
        pointsDisplay.Position = bodyDisplay.Position
        pointsDisplay.Visibility = 0
        # (ColorBy rescales the map to the data: the range set again)
        strainLut.AutomaticRescaleRangeMode = 'Never'
        strainLut.RescaleTransferFunction(0.0, args.strainMax)

    text = pv.Text()
    textDisplay = pv.Show(text, view)
    textDisplay.WindowLocation = 'Upper Center'
    textDisplay.FontSize = 18
    textDisplay.Color = black

    # A first render resets the camera: render before placing it
    pv.Render(view)
    # The tank over 82% of the width from the left, the colour bar right
    visible = [width/ppm, height/ppm]
    focal = [bounds[0] - 0.04*visible[0] + visible[0]/2,
             centre[1] + 12/ppm, centre[2]]
    view.CameraFocalPoint = focal
    view.CameraPosition = [focal[0], focal[1], focal[2] + 10*max(size)]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.CameraParallelProjection = 1
    view.CameraParallelScale = visible[1]/2

    stem = os.path.splitext(args.png)[0]
    panels = []
    for t in chosen:
        view.ViewTime = t
        if strainBar is not None:
            mesh = fetchBlocks(reader, t).get('/internalMesh')
            written = mesh is not None and \
                mesh.GetCellData().GetArray('soilFraction') is not None
            bodyDisplay.Visibility = 1 if written else 0
            pointsDisplay.Visibility = 0 if written else 1
        text.Text = 'soil column collapse: water speed and soil, t = %g s' % t
        panels.append(savePanel(pv, view, stem, t, width, height,
                                'picture.py'))
    pv.Delete(view)

    stackPanels(panels, args.png)
    print('picture.py: %s (%d panels)' % (args.png, len(panels)))
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))

#------------------------------------------------------------------------------
