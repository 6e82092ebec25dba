# SPDX-License-Identifier: GPL-3.0-or-later
"""A case opens in ParaView's OpenFOAM reader with its parcels and their
fields (run by pvpython; no display needed).

    pvpython checkReader.py CASE TIME CLOUD FIELD...

Requires, at TIME:
  - the reader's lagrangian/CLOUD block holds as many parcels as the
    cloud's own files (the count in TIME/lagrangian/CLOUD/d);
  - every FIELD is an array of that block, one value per parcel;
  - agglomerateId (if asked), d and T equal the cloud's files parcel by
    parcel: exactly for labels, to 1e-6 relative for scalars (the reader
    stores 32-bit floats, whose rounding is 6e-8 relative).
"""
import os
import sys

from paraview import servermanager
from paraview.simple import MergeBlocks, OpenFOAMReader

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'lib'))
from foamFiles import lagrangian_list as field  # noqa: E402


def main():
    case, time, cloud, fields = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
    ok = True
    foam = os.path.join(case, 'check.foam')
    open(foam, 'w').close()
    cdir = os.path.join(case, time, 'lagrangian', cloud)
    n_cloud = len(field(os.path.join(cdir, 'd'), 'd'))

    r = OpenFOAMReader(FileName=foam)
    r.MeshRegions = ['lagrangian/' + cloud]
    r.UpdatePipelineInformation()
    r.LagrangianArrays = fields
    merged = MergeBlocks(Input=r)
    merged.UpdatePipeline(float(time))
    data = servermanager.Fetch(merged)
    n_reader = data.GetNumberOfPoints()
    print(f'parcels: reader {n_reader}, cloud files {n_cloud}')
    if n_reader != n_cloud or n_cloud == 0:
        print('FAIL: the reader does not see the cloud\'s parcels')
        ok = False

    pd = data.GetPointData()
    for f in fields:
        arr = pd.GetArray(f)
        if arr is None:
            print(f'FAIL: no array {f} in the reader\'s cloud')
            ok = False
            continue
        print(f'{f}: {arr.GetNumberOfTuples()} tuples of {arr.GetNumberOfComponents()}')
        if arr.GetNumberOfTuples() != n_cloud:
            print(f'FAIL: {f} has not one value per parcel')
            ok = False
            continue
        kind = {'agglomerateId': 'i', 'd': 'd', 'T': 'd'}.get(f)
        if kind is None:
            continue
        ref = field(os.path.join(cdir, f), kind)
        got = [arr.GetValue(i) for i in range(n_cloud)]
        if kind == 'i':
            bad = sum(1 for a, b in zip(got, ref) if int(a) != b)
        else:
            bad = sum(1 for a, b in zip(got, ref)
                      if abs(a - b) > 1e-6 * abs(b))
        print(f'{f}: {bad} of {n_cloud} differ from the cloud\'s file')
        if bad:
            ok = False
    os.remove(foam)
    print('PASS' if ok else 'FAIL')
    sys.exit(0 if ok else 1)


main()
