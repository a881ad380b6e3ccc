#------------------------------------------------------------------------------
#   mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
#------------------------------------------------------------------------------
# Script
#     tests/lib/pvCheckCase.py
#
# Description
#     Headless check of a case's results through ParaView's OpenFOAM reader,
#     i.e. what a user will see in paraFoam. Run with pvpython (or pvbatch),
#     under a virtual X server:
#
#         xvfb-run -a pvpython tests/lib/pvCheckCase.py --case DIR \
#             [--time latest|T] [--field NAME:MIN:MAX ...] \
#             [--cloud NAME:N | --cloud NAME:NMIN:NMAX ...] \
#             [--cloud-field CLOUD:NAME:MIN:MAX ...] [--decomposed] \
#             [--png FILE [--resolution WxH] [--colour-by NAME]
#              [--cloud-colour-by NAME[:COMPONENT]:MIN:MAX]
#              [--cloud-body FRACTION] [--slice x|y|z] [--title TEXT]]
#
#     It opens the case's .foam file (DIR/<DIR's name>.foam, as paraFoam
#     -touch makes it, made empty if the case has none), goes to the requested
#     time (default: the latest one, the 0 directory included) and checks:
#       --field NAME:MIN:MAX          cell field NAME of the internal mesh is
#                                     there, finite, and its range lies within
#                                     [MIN, MAX] (vectors and tensors: range
#                                     of the magnitude)
#       --cloud NAME:N                lagrangian cloud NAME has N points
#       --cloud NAME:NMIN:NMAX        ... between NMIN and NMAX points
#       --cloud-field CLOUD:NAME:MIN:MAX   the same range check as --field on
#                                     a field of a lagrangian cloud
#     MIN and MAX may be 'inf' and '-inf'. With --png it renders the internal
#     mesh coloured by the first --field (or --colour-by), with a colour bar
#     titled with the field's units, the domain's outline, the title and
#     the time above it, and the clouds as points, sized to
#     about their spacing in the picture, dark grey or coloured by a field
#     of the cloud (--cloud-colour-by stress:YY:-2e5:0: the vertical stress,
#     components named as ParaView names them: X, Y, Z, XX, YY, ZZ, XY, YZ,
#     XZ, or Magnitude); with --cloud-body FRACTION the clouds are drawn as
#     a body instead: where the cell field FRACTION (soilFraction) is half
#     its largest or more, coloured by the --cloud-colour-by field spread
#     from the points (a sheared body drawn as points shows stripes).
#
#     Prints one 'PASS ...' or 'FAIL ...' line per check, then a summary,
#     and exits 1 if any check failed (2 on a usage error), 0 otherwise.
#
#     Notes on ParaView 5.11's reader (vtkOpenFOAMReader):
#       - time 0 is skipped unless SkipZeroTime is off (it is off here, but
#         the time list only changes after the reader's Refresh);
#       - a cloud is listed in MeshRegions as 'lagrangian/<cloudName>' once
#         any time directory holds <time>/lagrangian/<cloudName>/positions
#         (the '(x y z) celli' format; a cloud with only the barycentric
#         'coordinates' file is not seen); its fields are LagrangianArrays;
#       - the output is a multiblock: /internalMesh (unstructured grid) and
#         /lagrangian/<cloudName> (polydata, one vertex per particle, the
#         fields as both point and cell data, empty at times without it).
#------------------------------------------------------------------------------

import argparse
import os
import sys


def parseRange(text, what):
    """'-1e3' -> float; accepts inf/-inf"""
    try:
        return float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(
            "bad %s '%s' (not a number)" % (what, text))


def fieldSpec(text):
    """NAME:MIN:MAX -> (NAME, MIN, MAX)"""
    parts = text.rsplit(':', 2)
    if len(parts) != 3 or not parts[0]:
        raise argparse.ArgumentTypeError(
            "field check '%s' is not NAME:MIN:MAX" % text)
    lo = parseRange(parts[1], 'minimum')
    hi = parseRange(parts[2], 'maximum')
    if lo > hi:
        raise argparse.ArgumentTypeError(
            "field check '%s': minimum above maximum" % text)
    return (parts[0], lo, hi)


def cloudSpec(text):
    """NAME:N or NAME:NMIN:NMAX -> (NAME, NMIN, NMAX)"""
    parts = text.split(':')
    try:
        if len(parts) == 2 and parts[0]:
            n = int(parts[1])
            return (parts[0], n, n)
        if len(parts) == 3 and parts[0]:
            return (parts[0], int(parts[1]), int(parts[2]))
    except ValueError:
        pass
    raise argparse.ArgumentTypeError(
        "cloud check '%s' is not NAME:N or NAME:NMIN:NMAX" % text)


def cloudFieldSpec(text):
    """CLOUD:NAME:MIN:MAX -> (CLOUD, NAME, MIN, MAX)"""
    cloud, sep, rest = text.partition(':')
    if not sep or not cloud:
        raise argparse.ArgumentTypeError(
            "cloud field check '%s' is not CLOUD:NAME:MIN:MAX" % text)
    name, lo, hi = fieldSpec(rest)
    return (cloud, name, lo, hi)


def cloudColourSpec(text):
    """NAME[:COMPONENT]:MIN:MAX -> (name, component or None, (min, max))"""
    parts = text.split(':')
    if len(parts) not in (3, 4):
        raise argparse.ArgumentTypeError(
            "cloud colour '%s' is not NAME[:COMPONENT]:MIN:MAX" % text)
    lo, hi = parseRange(parts[-2], text), parseRange(parts[-1], text)
    return parts[0], (parts[1] if len(parts) == 4 else None), (lo, hi)


def resolutionSpec(text):
    """WxH -> [W, H]"""
    try:
        w, h = (int(x) for x in text.lower().split('x'))
        if w > 0 and h > 0:
            return [w, h]
    except ValueError:
        pass
    raise argparse.ArgumentTypeError("resolution '%s' is not WxH" % text)


def cloudRegion(name):
    """'materialPoints' or 'lagrangian/materialPoints' -> region name"""
    name = name.strip('/')
    return name if name.startswith('lagrangian/') else 'lagrangian/' + name


def parseArgs(argv):
    p = argparse.ArgumentParser(
        prog='pvCheckCase.py',
        description="Check a case's fields and clouds through ParaView's "
                    "OpenFOAM reader, and optionally render a PNG.")
    p.add_argument('--case', required=True, help='case directory')
    p.add_argument('--time', default='latest',
                   help="'latest' (default) or a time value")
    p.add_argument('--field', action='append', default=[], type=fieldSpec,
                   metavar='NAME:MIN:MAX',
                   help='check the range of a cell field (vectors: '
                        'magnitude); repeatable')
    p.add_argument('--cloud', action='append', default=[], type=cloudSpec,
                   metavar='NAME:N',
                   help='check that lagrangian cloud NAME has N points '
                        '(or NAME:NMIN:NMAX); repeatable')
    p.add_argument('--cloud-field', action='append', default=[],
                   type=cloudFieldSpec, metavar='CLOUD:NAME:MIN:MAX',
                   help='check the range of a field of a cloud; repeatable')
    p.add_argument('--decomposed', action='store_true',
                   help='read the processor* directories instead')
    p.add_argument('--png', help='render the result to this PNG file')
    p.add_argument('--slice', choices=['x', 'y', 'z'],
                   help='render a slice through the centre of the mesh, '
                        'normal to this axis (for 3D cases)')
    p.add_argument('--resolution', type=resolutionSpec, default=None,
                   metavar='WxH', help='PNG size (default 800x600, a 2D '
                   'domain\'s picture shaped to its aspect)')
    p.add_argument('--colour-by', '--color-by', dest='colourBy',
                   help='field to colour the mesh by in the PNG '
                        '(default: the first --field)')
    p.add_argument('--cloud-colour-by', '--cloud-color-by',
                   dest='cloudColourBy', type=cloudColourSpec, default=None,
                   metavar='NAME[:COMPONENT]:MIN:MAX',
                   help='field of the clouds to colour their points by in '
                        'the PNG, with its colour range')
    p.add_argument('--cloud-body', dest='cloudBody', default=None,
                   metavar='FRACTION',
                   help='draw the clouds as a body instead of points: the '
                        'mesh where the cell field FRACTION (the soil '
                        'fraction) is half its largest or more, coloured '
                        'by --cloud-colour-by spread from the points')
    p.add_argument('--title', default=None,
                   help='the picture\'s title (the time is added to it; '
                        'default: the case\'s name)')
    args = p.parse_args(argv)

    if args.time != 'latest':
        try:
            args.time = float(args.time)
        except ValueError:
            p.error("--time '%s' is neither 'latest' nor a number" % args.time)

    if not (args.field or args.cloud or args.cloud_field or args.png):
        p.error('nothing to do: give --field, --cloud, --cloud-field or --png')

    return args


#------------------------------------------------------------------------------
# Walking the reader's output

def blocksByPath(dataset, prefix='', found=None):
    """{'/internalMesh': vtkDataSet, '/lagrangian/cloud': ...} of the
    leaves of a multiblock, named as the reader names its blocks"""
    if found is None:
        found = {}
    if dataset is None:
        return found
    if dataset.IsA('vtkMultiBlockDataSet'):
        for i in range(dataset.GetNumberOfBlocks()):
            name = None
            if dataset.HasMetaData(i):
                name = dataset.GetMetaData(i).Get(dataset.NAME())
            blocksByPath(dataset.GetBlock(i),
                         prefix + '/' + (name or 'block%d' % i), found)
    elif dataset.IsA('vtkMultiPieceDataSet'):
        # Possible with a decomposed case read in parallel: keep the pieces
        pieces = [dataset.GetPiece(i)
                  for i in range(dataset.GetNumberOfPieces())]
        found[prefix] = [piece for piece in pieces if piece is not None]
    else:
        found[prefix] = dataset
    return found


def asList(dataset):
    if dataset is None:
        return []
    return dataset if isinstance(dataset, list) else [dataset]


def arrayValues(datasets, name, association):
    """(numpy values, components) of array NAME gathered over datasets,
    vectors and tensors as magnitudes; (None, 0) if a non-empty dataset
    lacks it; (empty array, 0) if all datasets are empty"""
    import numpy
    from vtk.util.numpy_support import vtk_to_numpy

    chunks = []
    nComp = 0
    for ds in datasets:
        if association == 'CELLS':
            data, size = ds.GetCellData(), ds.GetNumberOfCells()
        else:
            data, size = ds.GetPointData(), ds.GetNumberOfPoints()
        array = data.GetArray(name)
        if array is None:
            if size:
                return (None, 0)
            continue
        values = vtk_to_numpy(array).astype(float)
        nComp = array.GetNumberOfComponents()
        if nComp > 1:
            values = numpy.sqrt((values.reshape(-1, nComp)**2).sum(axis=1))
        chunks.append(values.ravel())
    if not chunks:
        return (numpy.zeros(0), 0) if datasets else (None, 0)
    return (numpy.concatenate(chunks), nComp)


def fmt(x):
    return '%.6g' % x


def checkRange(label, values, nComp, lo, hi, what):
    """One PASS/FAIL line for the range of values; returns True on PASS"""
    import numpy
    if values is None:
        print('FAIL %s: no such field' % label)
        return False
    if values.size == 0:
        print('FAIL %s: field is empty (0 %s)' % (label, what))
        return False
    bad = int(numpy.count_nonzero(~numpy.isfinite(values)))
    if bad:
        print('FAIL %s: %d of %d %s not finite (NaN/inf)'
              % (label, bad, values.size, what))
        return False
    vMin = float(values.min())
    vMax = float(values.max())
    ok = lo <= vMin and vMax <= hi
    print('%s %s: %s [%s, %s] %s [%s, %s] (%d %s)'
          % ('PASS' if ok else 'FAIL', label,
             'magnitude range' if nComp > 1 else 'range', fmt(vMin), fmt(vMax),
             'within' if ok else 'NOT within', fmt(lo), fmt(hi),
             values.size, what))
    return ok


#------------------------------------------------------------------------------
# Rendering

# The units of the fields the solver writes, for the colour bars' titles
UNITS = {
    'U': 'm/s', 'p': 'Pa', 'rho': 'kg/m3', 'soilFraction': '-',
    'alpha.water': '-', 'wallShearStress': 'Pa', 'fines': 'kg/m3',
    'soilVelocity': 'm/s', 'stress': 'Pa', 'plasticStrain': '-',
    'displacement': 'm', 'porosity': '-', 'velocity': 'm/s',
    'porePressure': 'Pa', 'finesContent': '-', 'mass': 'kg',
}


def barTitle(name, component=''):
    """A colour bar's title: the field, its component, its units"""
    title = name + (' ' + component if component else '')
    unit = UNITS.get(name)
    return title + (' [%s]' % unit if unit else '')


def placeBar(bar, slot):
    """A colour bar on the picture's right, below the title: the first
    (slot 0) in the lower half, a second one above it"""
    bar.WindowLocation = 'Any Location'
    bar.Orientation = 'Vertical'
    bar.Position = [0.8, 0.08 if slot == 0 else 0.5]
    bar.ScalarBarLength = 0.36


def render(args, reader, time, blocks, clouds, colourField):
    import paraview.simple as pv

    # Bounds of the internal mesh (the picture's shape and the camera)
    bounds = None
    for ds in asList(blocks.get('/internalMesh')):
        b = ds.GetBounds()
        if bounds is None:
            bounds = list(b)
        else:
            bounds = [min(bounds[0], b[0]), max(bounds[1], b[1]),
                      min(bounds[2], b[2]), max(bounds[3], b[3]),
                      min(bounds[4], b[4]), max(bounds[5], b[5])]

    if args.resolution:
        width, height = args.resolution
    else:
        # A flat domain's picture shaped to it (a wide tank is not drawn as
        # a strip in a tall white page, nor a column as a line), with room
        # for the title above and the colour bars beside
        width, height = 800, 600
        if bounds:
            size = sorted(bounds[2*i + 1] - bounds[2*i] for i in range(3))
            along = [bounds[2*i + 1] - bounds[2*i] for i in range(3)]
            if size[0] < 0.05*size[2] or getattr(args, 'slice', None):
                axes = [i for i in range(3) if
                        i != ('xyz'.index(args.slice) if args.slice
                              else min(range(3), key=lambda j: along[j]))]
                aspect = along[axes[0]]/max(along[axes[1]], 1e-300)
                if aspect > 1.5:
                    height = int(max(320, min(600, 700/aspect + 180)))
                elif aspect < 0.7:
                    width = int(max(640, min(800, 500*aspect + 480)))
    view = pv.CreateView('RenderView')
    view.ViewSize = [width, height]
    view.ViewTime = time
    view.OrientationAxesVisibility = 1
    try:
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    view.Background = [1.0, 1.0, 1.0]
    black = [0.0, 0.0, 0.0]

    # The internal mesh (or a slice through its centre), coloured by the
    # field
    mesh = pv.ExtractBlock(Input=reader, Selectors=['/Root/internalMesh'])
    sliceAxis = None
    if getattr(args, 'slice', None) and bounds:
        sliceAxis = 'xyz'.index(args.slice)
        normal = [0.0, 0.0, 0.0]
        normal[sliceAxis] = 1.0
        mesh = pv.Slice(Input=mesh)
        mesh.SliceType = 'Plane'
        mesh.SliceType.Origin = [(bounds[2*i] + bounds[2*i + 1])/2
                                 for i in range(3)]
        mesh.SliceType.Normal = normal
    meshDisplay = pv.Show(mesh, view)
    meshDisplay.Representation = 'Surface'
    body = getattr(args, 'cloudBody', None)
    if colourField and body and clouds and colourField[0] == body:
        # The fraction outlines the body drawn below: the space around it
        # is left plain (a second colour bar for it would only confuse)
        colourField = None
    if colourField:
        field, nComp, (vMin, vMax) = colourField
        if nComp > 1:
            pv.ColorBy(meshDisplay, ('CELLS', field, 'Magnitude'))
        else:
            pv.ColorBy(meshDisplay, ('CELLS', field))
        lut = pv.GetColorTransferFunction(field)
        if vMax <= vMin:
            vMax = vMin + max(abs(vMin), 1.0) * 1e-6
        lut.RescaleTransferFunction(vMin, vMax)
        pv.GetOpacityTransferFunction(field).RescaleTransferFunction(vMin, vMax)
        lut.AutomaticRescaleRangeMode = 'Never'
        meshDisplay.SetScalarBarVisibility(view, True)
        bar = pv.GetScalarBar(lut, view)
        placeBar(bar, 0)
        bar.Title = barTitle(field, 'magnitude' if nComp > 1 else '')
        bar.ComponentTitle = ''
        bar.TitleColor = black
        bar.LabelColor = black
        bar.RangeLabelFormat = '%-.4g'
    else:
        meshDisplay.ColorArrayName = ['POINTS', '']
        meshDisplay.AmbientColor = meshDisplay.DiffuseColor = [0.93, 0.93, 0.93]

    # The domain framed: its outline in black
    frame = pv.Show(pv.Outline(Input=mesh), view)
    frame.ColorArrayName = ['POINTS', '']
    frame.AmbientColor = frame.DiffuseColor = black
    frame.LineWidth = 1.5

    # Camera: along the thin direction of a 2D-like mesh (or the slice
    # normal), else isometric
    flat = False
    if bounds:
        size = [bounds[1] - bounds[0], bounds[3] - bounds[2],
                bounds[5] - bounds[4]]
        centre = [(bounds[2*i] + bounds[2*i + 1])/2 for i in range(3)]
        thin = min(range(3), key=lambda i: size[i])
        flat = size[thin] < 0.05 * max(size)
        if sliceAxis is not None:
            thin, flat = sliceAxis, True
        if flat:
            direction = [0.0, 0.0, 0.0]
            direction[thin] = 1.0
            up = [0.0, 0.0, 1.0] if thin != 2 else [0.0, 1.0, 0.0]
        else:
            direction = [1.0, -1.0, 1.0]
            up = [0.0, 0.0, 1.0]
        view.CameraFocalPoint = centre
        view.CameraPosition = [centre[i] + direction[i] for i in range(3)]
        view.CameraViewUp = up
    view.CameraParallelProjection = 1 if flat else 0
    # (a flat domain seen head-on needs no axes triad over it)
    view.OrientationAxesVisibility = 0 if flat else 1

    # The clouds, as points on top: in a 2D-like mesh particles lie inside
    # the slab, behind its front face, so they are moved out towards the
    # camera; in 3D the mesh is made see-through instead
    # Points about as large as their spacing in the picture (drawn larger
    # they merge into a solid blot): the spacing from the cloud's size
    pointSize = 6.0
    if bounds and clouds:
        inPlane = sorted(size)[1:] if flat else size
        nPoints = max(1, sum(ds.GetNumberOfPoints()
                             for region in clouds
                             for ds in asList(blocks.get('/' + region))))
        extent = max(inPlane)
        area = inPlane[0] * inPlane[1] if flat else None
        spacing = (area / nPoints) ** 0.5 if flat \
            else (size[0] * size[1] * size[2] / nPoints) ** (1.0 / 3.0)
        pixels = 0.8 * min(width, height) / max(extent, 1e-300)
        pointSize = min(6.0, max(1.5, 0.9 * spacing * pixels))
    for region in clouds:
        cloud = pv.ExtractBlock(Input=reader, Selectors=['/Root/' + region])
        cloudColour = getattr(args, 'cloudColourBy', None)
        if body and cloudColour and bounds:
            # The body: the fraction interpolated to the mesh's points and
            # clipped at half its largest (a smooth outline), the cloud's
            # field spread over it by a Gaussian kernel of 1.5 cells. Drawn
            # as points, a sheared body shows stripes where its rows of
            # points moved apart (tutorials/coupled/soilColumnCollapse's
            # README)
            fraction = pv.ExtractBlock(Input=reader,
                                       Selectors=['/Root/internalMesh'])
            largest = 0.0
            for ds in asList(blocks.get('/internalMesh')):
                a = ds.GetCellData().GetArray(body)
                if a is not None:
                    largest = max(largest, a.GetRange()[1])
            clip = pv.Clip(Input=pv.CellDatatoPointData(Input=fraction))
            clip.ClipType = 'Scalar'
            clip.Scalars = ['POINTS', body]
            clip.Value = 0.5*largest
            clip.Invert = 0
            cells = max(1, sum(ds.GetNumberOfCells()
                               for ds in asList(blocks.get('/internalMesh'))))
            dx = (max(size[0], 1e-300)*max(size[1], 1e-300)
                  *(size[2] if not flat else 1.0)/cells) \
                ** (1.0/(2 if flat else 3))
            spread = pv.PointDatasetInterpolator(
                Input=pv.MergeBlocks(Input=cloud),
                Source=pv.MergeBlocks(Input=clip))
            spread.Kernel = 'GaussianKernel'
            spread.Kernel.Radius = 1.5*dx
            spread.NullPointsStrategy = 'Closest Point'
            cloudDisplay = pv.Show(spread, view)
            cloudDisplay.Representation = 'Surface'
        else:
            cloudDisplay = pv.Show(cloud, view)
            cloudDisplay.Representation = 'Points'
        if cloudColour:
            name, component, (lo, hi) = cloudColour
            if component:
                pv.ColorBy(cloudDisplay, ('POINTS', name, component))
            else:
                pv.ColorBy(cloudDisplay, ('POINTS', name))
            lut = pv.GetColorTransferFunction(name)
            lut.ApplyPreset('Viridis (matplotlib)', True)
            lut.RescaleTransferFunction(lo, hi)
            lut.AutomaticRescaleRangeMode = 'Never'
            cloudDisplay.SetScalarBarVisibility(view, True)
            bar = pv.GetScalarBar(lut, view)
            bar.Title = barTitle(name, component)
            bar.ComponentTitle = ''
            bar.TitleColor = black
            bar.LabelColor = black
            bar.RangeLabelFormat = '%-.4g'
            placeBar(bar, 1 if colourField else 0)
        else:
            cloudDisplay.ColorArrayName = ['POINTS', '']
            cloudDisplay.AmbientColor = cloudDisplay.DiffuseColor = \
                [0.15, 0.15, 0.15]
        cloudDisplay.PointSize = pointSize
        try:
            cloudDisplay.RenderPointsAsSpheres = 1
        except AttributeError:
            pass
        if flat and body and cloudColour:
            # (the body on the mesh's front face, not inside the slab)
            meshDisplay.Opacity = 1.0
        if flat:
            shift = [0.0, 0.0, 0.0]
            shift[thin] = 1.01 * size[thin]
            cloudDisplay.Position = shift
        elif bounds:
            meshDisplay.Opacity = 0.35

    # The title and the time, above the picture
    title = getattr(args, 'title', None) \
        or 'case %s' % os.path.basename(os.path.abspath(args.case))
    text = pv.Text(Text='%s, t = %s s' % (title, fmt(time)))
    textDisplay = pv.Show(text, view)
    textDisplay.WindowLocation = 'Upper Center'
    textDisplay.FontSize = 16
    textDisplay.Justification = 'Center'
    textDisplay.Color = black

    view.ResetCamera()
    # (paraview.simple resets the camera at a view's first render: that
    # render done, the fit below stays)
    pv.Render(view)
    if flat and bounds:
        # The domain fitted to the picture, left of the colour bars and
        # below the title (ResetCamera fits the bounding sphere: a wide
        # tank came out as a thin strip)
        screenUp = 2 if thin != 2 else 1
        screenRight = [i for i in range(3) if i not in (thin, screenUp)][0]
        across, up = size[screenRight], size[screenUp]
        usable = 0.72          # of the width: the bars take the rest
        scale = 0.5*max(up/0.82, across/(0.92*usable)*height/width)
        focal = list(centre)
        # (the domain's centre at the middle of the usable part)
        focal[screenRight] += 0.5*(1 - usable)*2*scale*width/height
        focal[screenUp] += 0.04*2*scale
        view.CameraFocalPoint = focal
        view.CameraPosition = [focal[i] + (1.0 if i == thin else 0.0)
                               * max(size) for i in range(3)]
        view.CameraParallelScale = scale
    pv.Render(view)
    pngDir = os.path.dirname(os.path.abspath(args.png))
    if not os.path.isdir(pngDir):
        os.makedirs(pngDir)
    pv.SaveScreenshot(args.png, view, ImageResolution=[width, height])

    # Close the render window now: left to the interpreter's exit, a view
    # without a coloured representation ends in an X error (GLXBadContext)
    # that turns the exit status into 1
    pv.Delete(view)
    return width, height


#------------------------------------------------------------------------------

def main(argv):
    args = parseArgs(argv)

    caseDir = os.path.abspath(args.case)
    if not os.path.isdir(os.path.join(caseDir, 'system')):
        print('FAIL case %s: no such case (no system directory)' % caseDir)
        return 1

    # The case's own .foam file (paraFoam -touch makes <case name>.foam): one
    # per case, whoever opens it first
    existing = sorted(f for f in os.listdir(caseDir) if f.endswith('.foam'))
    foamFile = os.path.join(caseDir, existing[0] if existing
                            else os.path.basename(caseDir) + '.foam')
    if not os.path.exists(foamFile):
        open(foamFile, 'a').close()

    import paraview.simple as pv
    from paraview import servermanager

    reader = pv.OpenFOAMReader(FileName=foamFile)
    reader.CaseType = 'Decomposed Case' if args.decomposed \
        else 'Reconstructed Case'
    reader.SkipZeroTime = 0
    reader.Createcelltopointfiltereddata = 0
    reader.Adddimensionalunitstoarraynames = 0
    # The time list was made when FileName was set: make it again, with 0
    reader.Refresh()
    reader.UpdatePipelineInformation()

    nFail = 0
    nCheck = 0

    # Time
    times = reader.TimestepValues
    if isinstance(times, (int, float)):
        times = [times]
    times = sorted(float(t) for t in (times or []))
    if not times:
        print('FAIL time %s: the case has no time directories the reader can '
              'read' % args.time)
        return 1
    if args.time == 'latest':
        time = times[-1]
    else:
        time = min(times, key=lambda t: abs(t - args.time))
        if abs(time - args.time) > 1e-9 * max(1.0, abs(args.time)):
            print('FAIL time %s: not in the case (times: %s)'
                  % (fmt(args.time), ' '.join(fmt(t) for t in times)))
            return 1

    # Regions and arrays
    available = list(reader.GetProperty('MeshRegions').Available)
    regions = ['internalMesh']
    clouds = []
    for name in [c[0] for c in args.cloud] + [c[0] for c in args.cloud_field]:
        region = cloudRegion(name)
        if region in available and region not in regions:
            regions.append(region)
            clouds.append(region)
    reader.MeshRegions = regions
    reader.CellArrays = list(reader.CellArrays.Available)
    if clouds:
        reader.LagrangianArrays = list(reader.LagrangianArrays.Available)

    reader.UpdatePipeline(time)
    blocks = blocksByPath(servermanager.Fetch(reader))
    internal = asList(blocks.get('/internalMesh'))
    nCells = sum(ds.GetNumberOfCells() for ds in internal)

    print('pvCheckCase: case %s, time %s (times: %s), %d cells'
          % (caseDir, fmt(time), ' '.join(fmt(t) for t in times), nCells))

    # Fields of the internal mesh
    colourField = None
    for name, lo, hi in args.field:
        nCheck += 1
        values, nComp = arrayValues(internal, name, 'CELLS')
        if values is None:
            print('FAIL field %s @ t=%s: not found at this time '
                  '(cell fields of the case: %s)'
                  % (name, fmt(time), ', '.join(reader.CellArrays.Available)
                     or 'none'))
            nFail += 1
            continue
        if not checkRange('field %s @ t=%s' % (name, fmt(time)),
                          values, nComp, lo, hi, 'cells'):
            nFail += 1

    # Clouds
    cloudNames = ', '.join(r[len('lagrangian/'):] for r in available
                           if r.startswith('lagrangian/')) or 'none'
    for name, nMin, nMax in args.cloud:
        nCheck += 1
        region = cloudRegion(name)
        label = 'cloud %s @ t=%s' % (region[len('lagrangian/'):], fmt(time))
        if region not in available:
            print('FAIL %s: not found (clouds: %s; the reader needs '
                  '<time>/%s/positions)' % (label, cloudNames, region))
            nFail += 1
            continue
        n = sum(ds.GetNumberOfPoints()
                for ds in asList(blocks.get('/' + region)))
        expected = str(nMin) if nMin == nMax else '%d..%d' % (nMin, nMax)
        ok = nMin <= n <= nMax
        print('%s %s: %d points (expected %s)'
              % ('PASS' if ok else 'FAIL', label, n, expected))
        if not ok:
            nFail += 1

    for cloudName, name, lo, hi in args.cloud_field:
        nCheck += 1
        region = cloudRegion(cloudName)
        label = 'cloud field %s/%s @ t=%s' \
            % (region[len('lagrangian/'):], name, fmt(time))
        if region not in available:
            print('FAIL %s: cloud not found (clouds: %s)' % (label, cloudNames))
            nFail += 1
            continue
        values, nComp = arrayValues(asList(blocks.get('/' + region)), name,
                                    'POINTS')
        if values is None:
            print('FAIL %s: not found (cloud fields: %s)'
                  % (label, ', '.join(reader.LagrangianArrays.Available)
                     or 'none'))
            nFail += 1
            continue
        if not checkRange(label, values, nComp, lo, hi, 'points'):
            nFail += 1

    # Picture
    if args.png:
        fieldName = args.colourBy or (args.field[0][0] if args.field else None)
        if fieldName:
            values, nComp = arrayValues(internal, fieldName, 'CELLS')
            if values is not None and values.size:
                import numpy
                finite = values[numpy.isfinite(values)]
                if finite.size:
                    colourField = (fieldName, nComp,
                                   (float(finite.min()), float(finite.max())))
            if colourField is None:
                print('pvCheckCase: cannot colour by %s: not a cell field '
                      'with values; PNG shows the bare mesh' % fieldName)
        nCheck += 1
        if os.path.exists(args.png):
            os.remove(args.png)
        try:
            size = render(args, reader, time, blocks, clouds, colourField)
        except Exception as error:
            print('FAIL png %s: rendering failed: %s: %s'
                  % (args.png, type(error).__name__, error))
            nFail += 1
        else:
            written = os.path.isfile(args.png) \
                and os.path.getsize(args.png) > 0
            # An explicit --colour-by that cannot be shown is a failure too
            ok = written and (colourField is not None or not args.colourBy)
            print('%s png %s: %s%dx%d, coloured by %s'
                  % ('PASS' if ok else 'FAIL', args.png,
                     '' if written else 'NOT WRITTEN, ',
                     size[0], size[1],
                     colourField[0] if colourField else 'nothing'))
            if not ok:
                nFail += 1

    print('pvCheckCase: %d checks, %d failed' % (nCheck, nFail))
    return 1 if nFail else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))

#------------------------------------------------------------------------------
