"""Readers of the solid's VTK output written by jwlIbFoam and femdemFoam
(solidVtkWriter: XML, inline base64 with a UInt64 byte-count header), with
numpy only (no VTK or ParaView needed):
- read_vtu(path): every DataArray of a VTK/femdem_<i>.vtu by name, and
  "triangles" (n x 3) from its connectivity;
- read_vtp_lines(path): the segments (n x 2 x 2) of a VTK/cracks_<i>.vtp;
- read_vtp_line_fields(path): its CellData arrays by name (one value per
  line: initialJointLength, and with crackGas the crack gas's crackGas,
  p, rho, alpha.<material>, aperture).
"""
import base64
import xml.etree.ElementTree as ET

import numpy as np


def vtk_decode(arr, ncomp):
    """Inline base64 DataArray with a UInt64 byte-count header."""
    raw = base64.b64decode("".join(arr.text.split()))
    dtype = {"Float32": "<f4", "Float64": "<f8", "Int32": "<i4",
             "Int64": "<i8", "UInt8": "u1"}[arr.get("type")]
    n = int(np.frombuffer(raw[:8], "<u8")[0])
    data = np.frombuffer(raw[8:8 + n], dtype)
    return data.reshape(-1, ncomp) if ncomp > 1 else data


def read_vtu(path):
    root = ET.parse(path).getroot()
    out = {}
    for arr in root.iter("DataArray"):
        out[arr.get("Name")] = vtk_decode(arr, int(arr.get("NumberOfComponents", 1)))
    out["triangles"] = out["connectivity"].reshape(-1, 3)
    return out


def read_vtp_lines(path):
    root = ET.parse(path).getroot()
    arrs = {a.get("Name"): a for a in root.iter("DataArray")}
    if "Points" not in arrs or "connectivity" not in arrs:
        return np.zeros((0, 2, 2))
    pts = vtk_decode(arrs["Points"], 3)[:, :2]
    con = vtk_decode(arrs["connectivity"], 1).reshape(-1, 2)
    return pts[con]


def read_vtp_line_fields(path):
    root = ET.parse(path).getroot()
    out = {}
    for cd in root.iter("CellData"):
        for arr in cd.iter("DataArray"):
            out[arr.get("Name")] = vtk_decode(arr, 1)
    return out
