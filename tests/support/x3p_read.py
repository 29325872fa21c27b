"""Reads x3p files with two outside readers, x3pio and surfalize, for tests/core/output/x3p*.test.ts.

    python x3p_read.py FILE.x3p [FILE.x3p ...]

Prints one JSON document: the readers' versions, and for each file what each reader found (or the
error it raised): the grid size, the increments and offsets (metres for x3pio, micrometres for
surfalize), the metadata, and surfalize's height parameters (no levelling, no filter: the surface
as loaded). The heights x3pio read are written beside each file as FILE.x3pio.bin (float64
little-endian metres, in x3pio's row-major order), for a bit-for-bit comparison.

surfalize imports matplotlib, scipy, pandas, tqdm and PIL when it is imported, for plotting,
fitting and batch work; reading a file and its height parameters use only numpy. So that the test
does not install them (465 MB with them against 86 MB without), each one missing (tests/support/
ensure-python-x3p.mjs installs none of them) is replaced by a stub module that raises as soon as
anything taken from it is used (called, subclassed, indexed): a stub reached while reading or
computing would fail the test, never pass it silently. A full installation uses the real ones.
"""

import importlib.abc
import importlib.machinery
import importlib.util
import json
import sys
import warnings

STUBBED = ("matplotlib", "mpl_toolkits", "scipy", "pandas", "tqdm", "PIL")


class _Unusable:
    """What a stub module gives for any name: using it in any way raises."""

    def __init__(self, name):
        self._name = name

    def __getattr__(self, attribute):
        return _Unusable(f"{self._name}.{attribute}")

    def _fail(self, *args, **kwargs):
        raise RuntimeError(f"x3p_read.py: the stub {self._name} was used; install the real package")

    __call__ = __getitem__ = __iter__ = __mro_entries__ = __bool__ = __len__ = _fail


class _StubFinder(importlib.abc.MetaPathFinder, importlib.abc.Loader):
    """Provides a stub module for each of the given packages (and their submodules)."""

    def __init__(self, packages):
        self._packages = packages

    def find_spec(self, fullname, path=None, target=None):
        if fullname.split(".")[0] not in self._packages:
            return None
        return importlib.machinery.ModuleSpec(fullname, self, is_package=True)

    def create_module(self, spec):
        return None

    def exec_module(self, module):
        module.__path__ = []
        module.__getattr__ = lambda attribute: _Unusable(f"{module.__name__}.{attribute}")


def _stub_missing():
    """Stubs the packages of STUBBED that are not installed, and lists them."""
    missing = [name for name in STUBBED if importlib.util.find_spec(name) is None]
    if missing:
        sys.meta_path.append(_StubFinder(missing))
    return missing


def _read_x3pio(x3pio, path):
    x3p = x3pio.read(path)  # verify=True: the MD5 of main.xml and of bindata/data.bin are checked
    layer = x3p.layers[0]
    z = layer.z
    with open(path + ".x3pio.bin", "wb") as out:
        out.write(z.astype("<f8").tobytes())
    points = layer.points()
    corner = lambda row, column: [float(v) for v in points[row, column]]  # noqa: E731
    metadata = x3p.metadata
    return {
        "type": type(x3p).__name__,
        "revision": str(x3p.revision.value),
        "layers": len(x3p.layers),
        "shape": list(z.shape),
        "dtype": str(z.dtype),
        "xIncrement": float(x3p.header.x.increment),
        "yIncrement": float(x3p.header.y.increment),
        "zIncrement": float(x3p.header.z.increment),
        "zDataType": str(x3p.header.z.data_type.value),
        "xAxisType": str(x3p.header.x.axis_type.value),
        "offset": [float(v) for v in x3p.placement.offset],
        # x, y, z of the points (row 0, column 0), (row 0, column 1) and (row 1, column 0)
        "point00": corner(0, 0),
        "point01": corner(0, 1) if z.shape[1] > 1 else None,
        "point10": corner(1, 0) if z.shape[0] > 1 else None,
        "creator": metadata.creator,
        "comment": metadata.comment,
        "date": metadata.date.isoformat(),
        "probingType": str(metadata.probing_system.type.value),
        "instrumentModel": metadata.instrument.model,
    }


def _read_surfalize(surfalize, path):
    surface = surfalize.Surface.load(path)  # as loaded: no levelling, no filter, no form removal
    parameters = surface.height_parameters()
    data = surface.data
    with open(path + ".surfalize.bin", "wb") as out:
        out.write(data.astype("<f8").tobytes())
    return {
        "shape": list(data.shape),
        "stepXUm": float(surface.step_x),
        "stepYUm": float(surface.step_y),
        "parametersUm": {name: float(parameters[name]) for name in ("Sa", "Sq", "Sz", "Sp", "Sv", "Ssk", "Sku")},
        "sa": float(surface.Sa()),
        "sq": float(surface.Sq()),
        "sz": float(surface.Sz()),
    }


def main(paths):
    # Files with dx != dy are meant: the height parameters do not depend on the spacing.
    warnings.filterwarnings("ignore", message="The surface has different pixel size")
    stubbed = _stub_missing()
    import x3pio
    import surfalize

    report = {
        "versions": {"x3pio": x3pio.__version__, "surfalize": surfalize.__version__},
        "stubbed": stubbed,
        "files": [],
    }
    for path in paths:
        entry = {"path": path}
        for name, read, module in (("x3pio", _read_x3pio, x3pio), ("surfalize", _read_surfalize, surfalize)):
            try:
                entry[name] = read(module, path)
            except Exception as error:  # noqa: BLE001 - the test shows which reader refused which file
                entry[name] = {"error": f"{type(error).__name__}: {error}"}
        report["files"].append(entry)
    json.dump(report, sys.stdout)


if __name__ == "__main__":
    main(sys.argv[1:])
