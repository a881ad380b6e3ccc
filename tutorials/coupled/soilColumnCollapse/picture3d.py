#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     tutorials/coupled/soilColumnCollapse/picture3d.py
#
# Description
#     The paper's Fig. 5 in 3D (./Allrun -3d) through ParaView's OpenFOAM
#     reader, seen in perspective from the front, right and above: the
#     water's speed |U| on the back wall (the first cell layer, z = dx/2) and
#     on the mid-plane (z = 2 m; only ahead of the soil, so that it hides
#     neither the soil nor the back wall), one colour range for all panels,
#     and the soil's material points as a body of discs ('Point Gaussian',
#     radius dx/4), coloured by their displacement |x - x0| from the first
#     written time (points matched by origProcId and origId; a colour range
#     of its own, the same for all panels). Run with pvpython under a
#     virtual X server:
#
#         xvfb-run -a pvpython picture3d.py [--case DIR] [--times 0 3 6]
#             [--png soilColumnCollapse3d.png] [--width 1000]
#             [--mid clip|translucent]
#
#     Writes one PNG per time (<png stem>_t<time>.png; the nearest written
#     time is taken, each once) and the panels stacked top to bottom in
#     <png>. Prints the times, the colour ranges and the files; exits 1 if
#     nothing could be rendered.
#------------------------------------------------------------------------------

import argparse
import os
import sys

# The reader's blocks, the water's speed range, the time in file names and
# the stacking of the panels: as the pseudo-2D picture does them
sys.dont_write_bytecode = True     # (no __pycache__ in the case folder)
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from picture import (fetchBlocks, openCase, savePanel,  # noqa: E402
                     speedRange, stackPanels, styleBar)


def parseArgs(argv):
    p = argparse.ArgumentParser(prog='picture3d.py')
    p.add_argument('--case', default='.')
    p.add_argument('--times', type=float, nargs='+', default=[0.0, 3.0, 6.0])
    p.add_argument('--png', default='soilColumnCollapse3d.png')
    p.add_argument('--width', type=int, default=1000)
    p.add_argument('--mid', choices=['clip', 'translucent'], default='clip',
                   help='mid-plane only ahead of the soil front (clip) or '
                        'all of it, see-through (translucent)')
    return p.parse_args(argv)


def cloudPoints(ds):
    """(keys, positions) of a cloud: the key origProcId*2^32 + origId names
    a point for all its life (origId alone repeats across processors)"""
    import numpy
    from vtk.util.numpy_support import vtk_to_numpy
    if ds is None or ds.GetNumberOfPoints() == 0:
        return None
    data = ds.GetPointData()
    if data.GetArray('origId') is None:
        return None
    ids = vtk_to_numpy(data.GetArray('origId')).astype(numpy.int64).ravel()
    procs = data.GetArray('origProcId')
    procs = 0 if procs is None \
        else vtk_to_numpy(procs).astype(numpy.int64).ravel()
    # The field x if written, else the reader's points (from 'positions')
    x = data.GetArray('x')
    x = ds.GetPoints().GetData() if x is None else x
    return (procs << 32) + ids, vtk_to_numpy(x).astype(float).reshape(-1, 3)


def soilPolyData(x, d):
    """A vtkPolyData of the points x with 'displacement' (no cells: the
    Point Gaussian representation draws the points themselves)"""
    import vtk
    from vtk.util.numpy_support import numpy_to_vtk
    points = vtk.vtkPoints()
    points.SetData(numpy_to_vtk(x.copy(), deep=1))
    poly = vtk.vtkPolyData()
    poly.SetPoints(points)
    array = numpy_to_vtk(d.copy(), deep=1)
    array.SetName('displacement')
    poly.GetPointData().AddArray(array)
    return poly


def main(argv):
    import numpy
    args = parseArgs(argv)
    import paraview.simple as pv
    caseDir = os.path.abspath(args.case)
    cloud = 'lagrangian/materialPoints'
    reader = openCase(caseDir)
    reader.CellArrays = ['U']
    reader.LagrangianArrays = [a for a in ['x', 'origId', 'origProcId']
                               if a in reader.LagrangianArrays.Available]

    times = reader.TimestepValues
    if isinstance(times, (int, float)):
        times = [times]
    times = sorted(float(t) for t in (times or []))
    if not times:
        print('picture3d.py: no time directories in %s' % caseDir)
        return 1
    chosen = []
    for t in args.times:
        near = min(times, key=lambda s: abs(s - t))
        if near not in chosen:
            chosen.append(near)

    # The soil's first positions, sorted by key for the look-up
    first = cloudPoints(fetchBlocks(reader, times[0]).get('/' + cloud))
    if first is not None:
        order = numpy.argsort(first[0])
        keys0, x0 = first[0][order], first[1][order]

    # Per time: the water's largest speed (one colour range for all) and
    # the soil with its displacement (one colour range for all too)
    uMax, dMax, frames = 0.0, 0.0, []
    for t in chosen:
        blocks = fetchBlocks(reader, t)
        mesh = blocks.get('/internalMesh')
        s = speedRange(mesh) if mesh is not None else None
        if s is None:
            print('picture3d.py: no mesh or no finite U at t = %g: skipped' % t)
            continue
        bounds = mesh.GetBounds()
        cell = mesh.GetCell(0).GetBounds()
        dx = cell[1] - cell[0]
        uMax = max(uMax, s)
        soil = cloudPoints(blocks.get('/' + cloud)) \
            if first is not None else None
        if soil is not None:
            keys, x = soil
            at = numpy.minimum(numpy.searchsorted(keys0, keys), len(keys0) - 1)
            found = keys0[at] == keys
            if not found.all():
                print('picture3d.py: t = %g: %d points not in the first time, '
                      'left out' % (t, (~found).sum()))
            x, d = x[found], numpy.sqrt(((x[found] - x0[at[found]])**2)
                                        .sum(axis=1))
            dMax = max(dMax, float(d.max()) if d.size else 0.0)
            soil = (soilPolyData(x, d), float(x[:, 0].max()) if d.size
                    else bounds[0])
        frames.append((t, soil))
    if not frames:
        print('picture3d.py: nothing to render in %s' % caseDir)
        return 1
    uMax = uMax if uMax > 0 else 1.0
    dRange = dMax if dMax > 0 else 1.0
    print('picture3d.py: times %s, water speed 0 to %.4g m/s, '
          'soil displacement 0 to %.4g m, dx %g m'
          % (' '.join('%g' % f[0] for f in frames), uMax, dMax, dx))

    size = [bounds[1] - bounds[0], bounds[3] - bounds[2],
            bounds[5] - bounds[4]]
    centre = [(bounds[2*i] + bounds[2*i + 1])/2 for i in range(3)]
    width = args.width
    height = int(round(0.62*width))

    view = pv.CreateView('RenderView')
    view.ViewSize = [width, height]
    view.OrientationAxesVisibility = 0
    try:
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    view.Background = [1.0, 1.0, 1.0]

    internal = pv.ExtractBlock(Input=reader, Selectors=['/Root/internalMesh'])
    # The tank's edges, for the eye
    outline = pv.Show(pv.Outline(Input=internal), view)
    outline.AmbientColor = outline.DiffuseColor = [0.3, 0.3, 0.3]

    # Back wall: the first cell layer's centres; mid-plane: just off the
    # cell faces at z = 2 m (nz even), where a slice would give each face
    # twice, from both neighbouring cells
    def zSlice(z):
        cut = pv.Slice(Input=internal, SliceType='Plane')
        cut.SliceType.Origin = [centre[0], centre[1], z]
        cut.SliceType.Normal = [0.0, 0.0, 1.0]
        return cut
    back = zSlice(bounds[4] + dx/2)
    mid = zSlice(centre[2] + 1e-3*dx)
    clip = None
    if args.mid == 'clip':
        # Whole cells only ahead of the soil front (origin set per time)
        clip = pv.Clip(Input=mid, ClipType='Plane')
        clip.ClipType.Normal = [1.0, 0.0, 0.0]
        clip.Invert = 0
        clip.Crinkleclip = 1
        mid = clip

    lut = pv.GetColorTransferFunction('U')
    try:
        lut.ApplyPreset('Turbo', True)
    except Exception:
        lut.ApplyPreset('Jet', True)
    for source in (back, mid):
        display = pv.Show(source, view)
        display.Representation = 'Surface'
        pv.ColorBy(display, ('CELLS', 'U', 'Magnitude'))
        if source is mid and args.mid == 'translucent':
            display.Opacity = 0.45
    # After ColorBy, which rescales to the data at the view's time
    lut.RescaleTransferFunction(0.0, uMax)
    lut.AutomaticRescaleRangeMode = 'Never'
    display.SetScalarBarVisibility(view, True)
    styleBar(pv.GetScalarBar(lut, view), 'water speed [m/s]',
             [0.91, 0.2])

    # The soil: one disc per point, radius dx/4 (2 points per cell and
    # direction: neighbours touch, the body looks continuous). Flat discs:
    # shaded spheres ('Sphere') are 1 to 3 pixels here and give a moire
    producer = pv.PVTrivialProducer()
    soilDisplay = None
    soils = [f[1][0] for f in frames if f[1] is not None]
    if soils:
        producer.GetClientSideObject().SetOutput(soils[0])
        soilDisplay = pv.Show(producer, view)
        soilDisplay.Representation = 'Point Gaussian'
        soilDisplay.GaussianRadius = dx/4
        soilDisplay.ShaderPreset = 'Plain circle'
        pv.ColorBy(soilDisplay, ('POINTS', 'displacement'))
        soilLut = pv.GetColorTransferFunction('displacement')
        soilLut.ApplyPreset('BrOrYl', True)
        soilLut.RescaleTransferFunction(0.0, dRange)
        soilLut.AutomaticRescaleRangeMode = 'Never'
        soilDisplay.SetScalarBarVisibility(view, True)
        styleBar(pv.GetScalarBar(soilLut, view), 'soil displacement [m]',
                 [0.80, 0.2])
    else:
        print('picture3d.py: no soil points (cloud %s with origId) shown'
              % cloud)

    # The time above, what the two planes are below
    text = pv.Text()
    pv.Show(text, view, WindowLocation='Upper Center', FontSize=18,
            Color=[0.0, 0.0, 0.0])
    legend = pv.Text(Text='water speed on the back wall (z = %g m) and the '
                     'mid-plane (z = %g m%s)'
                     % (bounds[4] + dx/2, centre[2],
                        ', ahead of the soil' if clip else ', see-through'))
    pv.Show(legend, view, WindowLocation='Lower Left Corner', FontSize=13,
            Color=[0.0, 0.0, 0.0])

    # A first render resets the camera: render before placing it. Then in
    # perspective from the front (+z), right (+x, 35 degrees) and above (22
    # degrees): the soil's front face and top both seen, the whole tank in
    # the left 80% of the picture, the colour bars right of it
    pv.Render(view)
    az, el, dist = numpy.radians(35), numpy.radians(22), 1.6*size[0]
    focal = [centre[0] + 0.15*size[0], centre[1], centre[2]]
    view.CameraFocalPoint = focal
    view.CameraPosition = [focal[0] + dist*numpy.cos(el)*numpy.sin(az),
                           focal[1] + dist*numpy.sin(el),
                           focal[2] + dist*numpy.cos(el)*numpy.cos(az)]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.CameraViewAngle = 30

    stem = os.path.splitext(args.png)[0]
    panels = []
    for t, soil in frames:
        view.ViewTime = t
        if clip is not None:
            front = soil[1] if soil is not None else bounds[0]
            clip.ClipType.Origin = [front + dx, centre[1], centre[2]]
        if soilDisplay is not None:
            soilDisplay.Visibility = int(soil is not None)
            if soil is not None:
                producer.GetClientSideObject().SetOutput(soil[0])
                producer.MarkModified(producer)
                producer.UpdatePipeline()
        text.Text = 'soil column collapse, 3D: water speed and soil ' \
            'displacement, t = %g s' % t
        panels.append(savePanel(pv, view, stem, t, width, height,
                                'picture3d.py'))
    pv.Delete(view)

    stackPanels(panels, args.png)
    print('picture3d.py: %s (%d panels)' % (args.png, len(panels)))
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))

#------------------------------------------------------------------------------
