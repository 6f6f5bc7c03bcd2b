# Opens an XDMF sidecar with ParaView's readers, as a user does, and prints
# what ParaView sees as one JSON object: for each reader (XDMFReader, and
# Xdmf3ReaderS, which File > Open and OpenDataFile pick), the data class,
# dimensions, origin, spacing, bounds, time steps and the value of ARRAY at
# the point nearest to (X, Y, 0) at TIME (or the first step), and the bounds
# of Warp By Scalar of ARRAY (scale 1).
#   pvpython paraview_probe.py FILE.xdmf ARRAY X Y [TIME]
import json
import os
import sys

from paraview import servermanager
from paraview.simple import Delete, WarpByScalar, XDMFReader, Xdmf3ReaderS


def probe(make_reader, path, array, x, y, time):
    reader = make_reader(path)
    times = list(reader.TimestepValues) if reader.TimestepValues else []
    if time is None and times:
        time = times[0]
    if time is None:
        reader.UpdatePipeline()
    else:
        reader.UpdatePipeline(time)
    data = servermanager.Fetch(reader)
    while data.IsA("vtkMultiBlockDataSet"):
        data = data.GetBlock(0)
    out = {"class": data.GetClassName(), "dims": list(data.GetDimensions()), "origin": list(data.GetOrigin()),
           "spacing": list(data.GetSpacing()), "bounds": list(data.GetBounds()), "times": times}
    point = data.FindPoint(x, y, 0.0)
    values = data.GetPointData().GetArray(array)
    out["point"] = list(data.GetPoint(point)) if point >= 0 else None
    out["value"] = values.GetValue(point) if point >= 0 and values is not None else None
    warp = WarpByScalar(Input=reader, Scalars=["POINTS", array], ScaleFactor=1.0)
    if time is None:
        warp.UpdatePipeline()
    else:
        warp.UpdatePipeline(time)
    out["warp_bounds"] = list(servermanager.Fetch(warp).GetBounds())
    Delete(warp)
    Delete(reader)
    return out


def main():
    path = os.path.abspath(sys.argv[1])  # Xdmf3ReaderS resolves the HDF5 file wrongly from a relative name
    array, x, y = sys.argv[2], float(sys.argv[3]), float(sys.argv[4])
    time = float(sys.argv[5]) if len(sys.argv) > 5 else None
    result = {
        "XDMFReader": probe(lambda p: XDMFReader(FileNames=[p]), path, array, x, y, time),
        "Xdmf3ReaderS": probe(lambda p: Xdmf3ReaderS(FileName=[p]), path, array, x, y, time),
    }
    print("PROBE " + json.dumps(result))


main()
