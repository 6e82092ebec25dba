# SPDX-License-Identifier: GPL-3.0-or-later
# The ParaView side of bin/sinterRender, run by pvbatch under xvfb-run.
# Arguments are checked by sinterRender; this script only draws.
import argparse
import os

from paraview.simple import (ColorBy, GetColorTransferFunction, Glyph,
                             MergeBlocks, OpenFOAMReader, Outline, Render,
                             SaveScreenshot, CreateView, Show, Hide, Slice,
                             Text, GetScalarBar)

ap = argparse.ArgumentParser()
ap.add_argument('--foam', required=True)
ap.add_argument('--cloud', required=True)
ap.add_argument('--out', required=True)
ap.add_argument('--size', nargs=2, type=int, required=True)
ap.add_argument('--fields', nargs='+', required=True)
ap.add_argument('--times', nargs='+', required=True)
ap.add_argument('--range', nargs='+', default=[])   # FIELD LO HI ...
a = ap.parse_args()
fixed = {a.range[i]: (float(a.range[i + 1]), float(a.range[i + 2]))
         for i in range(0, len(a.range), 3)}



def reader(regions):
    r = OpenFOAMReader(FileName=a.foam)
    r.CaseType = 'Reconstructed Case'
    r.MeshRegions = regions
    r.Createcelltopointfiltereddata = 0
    r.UpdatePipelineInformation()
    return r


mesh = reader(['internalMesh'])
parts = reader(['lagrangian/' + a.cloud])
available = list(parts.GetProperty('LagrangianArrayInfo')[::2])
wanted = [f for f in a.fields if f in available]
for f in a.fields:
    if f not in available:
        print(f"sinterRender: no field '{f}' on cloud '{a.cloud}'"
              f" (fields: {' '.join(available)}); skipped")
if 'd' not in available:
    raise SystemExit(f"sinterRender: cloud '{a.cloud}' has no diameter field d")
parts.LagrangianArrays = sorted(set(wanted + ['d']))
cellFields = list(mesh.GetProperty('CellArrayInfo')[::2])
mesh.CellArrays = ['voidage'] if 'voidage' in cellFields else []

merged = MergeBlocks(Input=parts)
spheres = Glyph(Input=merged, GlyphType='Sphere')
spheres.ScaleArray = ['POINTS', 'd']      # sphere glyph radius 0.5: diameter d
spheres.ScaleFactor = 1.0
spheres.OrientationArray = ['POINTS', 'No orientation array']
spheres.GlyphMode = 'All Points'
spheres.GlyphType.ThetaResolution = 12
spheres.GlyphType.PhiResolution = 12
outline = Outline(Input=mesh)

view = CreateView('RenderView')
view.ViewSize = a.size
view.OrientationAxesVisibility = 0
try:
    view.UseColorPaletteForBackground = 0
except AttributeError:
    pass
view.Background = [1.0, 1.0, 1.0]
view.CameraParallelProjection = 1

titles = {'U': 'particle speed [m/s]', 'T': 'particle temperature [K]',
          'agglomerateId': 'agglomerate (grey: free)', 'd': 'parcel diameter [m]',
          'voidage': 'gas voidage'}


def frame(bounds):
    """Look at the box bounds from -y, z up, the box filling the height."""
    cx, cy, cz = [(bounds[2 * i] + bounds[2 * i + 1]) / 2 for i in range(3)]
    dx, dy, dz = [bounds[2 * i + 1] - bounds[2 * i] for i in range(3)]
    view.CameraFocalPoint = [cx, cy, cz - 0.06 * dz]   # room for the bar
    view.CameraPosition = [cx, cy - 4 * max(dy, dx, dz), cz - 0.06 * dz]
    view.CameraViewUp = [0, 0, 1]
    aspect = a.size[1] / a.size[0]
    view.CameraParallelScale = 0.62 * max(dz, dx * aspect)


def colour(display, array, assoc, field, lo, hi, preset):
    ColorBy(display, (assoc, array) if field != 'U' else (assoc, array, 'Magnitude'))
    lut = GetColorTransferFunction(array)
    lut.ApplyPreset(preset, True)
    lut.RescaleTransferFunction(lo, hi)
    lut.AutomaticRescaleRangeMode = 'Never'
    if field == 'agglomerateId':
        lut.UseBelowRangeColor = 1
        lut.BelowRangeColor = [0.75, 0.75, 0.75]
    bar = GetScalarBar(lut, view)
    bar.Title = titles.get(field, field)
    bar.ComponentTitle = ''
    bar.TitleColor = bar.LabelColor = [0, 0, 0]
    bar.TitleFontSize = bar.LabelFontSize = 14
    bar.WindowLocation = 'Any Location'
    bar.Orientation = 'Horizontal'
    bar.Position = [0.1, 0.02]
    bar.ScalarBarLength = 0.8
    bar.AutomaticLabelFormat = 0
    bar.LabelFormat = bar.RangeLabelFormat = '%-#.3g'
    display.SetScalarBarVisibility(view, True)
    return lut


def array_range(proxy, assoc, name, component=-1):
    info = proxy.GetDataInformation().DataInformation
    arrays = (info.GetPointDataInformation() if assoc == 'POINTS'
              else info.GetCellDataInformation())
    ai = arrays.GetArrayInformation(name)
    return ai.GetComponentRange(component) if ai else (0.0, 1.0)


# One colour range per field over all the times, so pictures compare
# (but the speed's of each time: the filling's fall would drown the bed's)
ranges = {}
most = 0
for t in a.times:
    merged.UpdatePipeline(float(t))
    n = merged.GetDataInformation().GetNumberOfPoints()
    most = max(most, n)
    if n == 0:
        continue
    for field in wanted:
        lo, hi = array_range(merged, 'POINTS', field, -1 if field == 'U' else 0)
        if field in ranges:
            lo, hi = min(lo, ranges[field][0]), max(hi, ranges[field][1])
        ranges[field] = (lo, hi)

# Coarser spheres for large beds (software rendering)
if most > 20000:
    spheres.GlyphType.ThetaResolution = 8
    spheres.GlyphType.PhiResolution = 6

for t in a.times:
    tv = float(t)
    for p in (mesh, parts, merged, spheres, outline):
        p.UpdatePipeline(tv)
    view.ViewTime = tv
    bounds = mesh.GetDataInformation().GetBounds()
    n = merged.GetDataInformation().GetNumberOfPoints()
    if n == 0:
        print(f'sinterRender: no parcels at time {t}; nothing drawn')
        continue
    label = Text(Text=f't = {t} s, {n} parcels')
    for field in wanted:
        lo, hi = ranges[field]
        if field in fixed:
            lo, hi = fixed[field]
        elif field == 'U':
            lo = 0.0
            hi = max(array_range(merged, 'POINTS', 'U', -1)[1], 1e-12)
        elif field == 'agglomerateId':
            lo, hi = 0.0, max(hi, 1.0)
        elif hi - lo < 1e-9 * max(1.0, abs(hi)):
            lo, hi = lo - 0.5, hi + 0.5
        ds = Show(spheres, view)
        preset = {'U': 'Viridis (matplotlib)', 'T': 'Inferno (matplotlib)',
                  'agglomerateId': 'Turbo'}.get(field, 'Cool to Warm')
        colour(ds, field, 'POINTS', field, lo, hi, preset)
        do = Show(outline, view)
        do.DiffuseColor = do.AmbientColor = [0.3, 0.3, 0.3]
        dl = Show(label, view)
        dl.Color = [0, 0, 0]
        dl.FontSize = 14
        dl.WindowLocation = 'Upper Center'
        Render(view)            # the first render resets the camera
        frame(bounds)
        Render(view)
        path = os.path.join(a.out, f'particles_{field}_{t}.png')
        SaveScreenshot(path, view, ImageResolution=a.size)
        print(f'sinterRender: wrote {path} ({n} parcels, colours'
              f' {lo:g} to {hi:g})')
        Hide(spheres, view)
        Hide(outline, view)
        Hide(label, view)
        GetScalarBar(GetColorTransferFunction(field), view).Visibility = 0

    if 'voidage' in mesh.CellArrays:
        cut = Slice(Input=mesh)
        cut.SliceType = 'Plane'
        cx = (bounds[0] + bounds[1]) / 2
        cy = (bounds[2] + bounds[3]) / 2
        cz = (bounds[4] + bounds[5]) / 2
        cut.SliceType.Origin = [cx, cy, cz]
        cut.SliceType.Normal = [0, 1, 0]
        cut.UpdatePipeline(tv)
        dc = Show(cut, view)
        colour(dc, 'voidage', 'CELLS', 'voidage', 0.35, 1.0, 'Viridis (matplotlib)')
        do = Show(outline, view)
        dl = Show(label, view)
        dl.Color = [0, 0, 0]
        dl.WindowLocation = 'Upper Center'
        Render(view)
        frame(bounds)
        Render(view)
        path = os.path.join(a.out, f'voidage_{t}.png')
        SaveScreenshot(path, view, ImageResolution=a.size)
        print(f'sinterRender: wrote {path}')
        Hide(cut, view)
        Hide(outline, view)
        GetScalarBar(GetColorTransferFunction('voidage'), view).Visibility = 0
    Hide(label, view)
