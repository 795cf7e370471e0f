"""The atlas (verify.atlas, ``paramres atlas``) and its engine (verify.engine): computed on a
local dask cluster of 2 worker processes it equals the same points from ``boundary`` and
``table``; an interrupted Zarr atlas resumes to the same dataset; the netCDF opens with netCDF4
and h5netcdf; bad input is refused before any work, nothing written."""

from __future__ import annotations

import math
from fractions import Fraction

import mpmath
import numpy as np
import pytest

xr = pytest.importorskip("xarray")
distributed = pytest.importorskip("distributed")

from reports.cli import main  # noqa: E402
from reports.commands.table import rows  # noqa: E402
from verify.atlas import atlas, request  # noqa: E402
from verify.growth import growth_map  # noqa: E402
from verify.inputs import InputError  # noqa: E402
from verify.modulation import boundary  # noqa: E402

ORDERS, M, Q, DIGITS, T = "1-3", "0.1:0.5:0.2", "none,7", 20, "0.3:2.1:0.6"
EDGE_VARS = ("lower_text", "upper_text", "lower", "upper", "lower_min", "upper_max", "exists")


@pytest.fixture(scope="module")
def client():
    """A local cluster of 2 single-threaded worker processes, shared by the module."""
    with (
        distributed.LocalCluster(
            n_workers=2,
            threads_per_worker=1,
            processes=True,
            dashboard_address=None,
            silence_logs=50,
        ) as cluster,
        distributed.Client(cluster, set_as_default=False) as c,
    ):
        yield c


@pytest.fixture(scope="module")
def full(client, tmp_path_factory):
    """The reference atlas, on the cluster, to netCDF."""
    path = tmp_path_factory.mktemp("atlas") / "full.nc"
    ds = atlas(ORDERS, M, Q=Q, T=T, digits=DIGITS, output=path, scheduler=client, edge_chunk=2)
    return path, ds


def test_atlas_on_two_workers_equals_boundary_and_table(full):
    _path, ds = full
    req = request(ORDERS, M, Q=Q, T=T, digits=DIGITS)
    for q, Qv in enumerate(req.Q):
        table = rows(list(req.orders), list(req.m), Qv, "exact", DIGITS)
        for o, n in enumerate(req.orders):
            for j, m in enumerate(req.m):
                b = boundary(n, m, Q=Qv, digits=DIGITS)
                here = ds.isel(system=0, duty=0, Q=q, order=o, m=j)
                assert bool(here.exists) == b.exists
                row = next(r for r in table if r[0] == n and r[1] == m)
                if not b.exists:
                    assert row[2] is None and math.isnan(float(here.lower))
                    continue
                j_b = b.as_json()
                # the same certified text as boundary and as table (same digits)
                assert str(here.lower_text.values) == j_b["lower"] == row[2]
                assert str(here.upper_text.values) == j_b["upper"] == row[3]
                # the double is the nearest to the certified value; the bounds enclose the
                # exact edge (boundary's enclosure, rounded outwards)
                assert float(here.lower) == float(b.lower)
                assert mpmath.mpf(float(here.lower_min)) <= b.lower_enclosure[0]
                assert mpmath.mpf(float(here.upper_max)) >= b.upper_enclosure[1]
                assert float(here.lower_min) <= float(here.lower) <= float(here.lower_max)


def test_growth_and_thresholds_in_the_atlas(full):
    _path, ds = full
    req = request(ORDERS, M, Q=Q, T=T, digits=DIGITS)
    tau = np.array([float(t) for t in req.T])
    m = np.array([float(x) for x in req.m])
    for q, Qv in enumerate(req.Q):
        ref = growth_map(tau, m, None if Qv is None else float(Qv))
        assert np.array_equal(ds.growth.isel(system=0, duty=0, Q=q).values, ref)
    # thresholds where Q is finite: the first depth of verify.existence, enclosed
    from verify.existence import existence

    q7 = list(req.Q).index(Fraction(7))
    for o, n in enumerate(req.orders):
        ex = existence(n, 7, digits=DIGITS)
        first = next(t for t in ex.thresholds if t.appears)
        here = ds.isel(system=0, duty=0, Q=q7, order=o)
        assert str(here.threshold_text.values) == first.text()
        lo, hi = first.enclosure
        assert float(here.threshold_min) <= lo and float(here.threshold_max) >= hi
    assert np.all(np.isnan(ds.threshold.isel(Q=list(req.Q).index(None)).values))


def test_thresholds_for_another_system_and_duty():
    """Thresholds are computed for every system and duty of the grid, not only the paper's: each
    equals the one ``paramres.existence`` proves for that system and duty (the same proof, run
    independently here), and the dims are those of the edges."""
    import paramres

    ds = paramres.atlas(
        "1,2", ["0.3"], Q="none,7", system="pendulum,torsion", duty="1/3", digits=15, workers=1
    )
    assert ds.threshold.dims == ("system", "duty", "Q", "order")
    assert ds.threshold_text.dims == ds.threshold.dims
    q7 = list(ds.Q.values).index(7.0)
    seen = set()
    for s, name in enumerate(ds.system.values):
        for o, n in enumerate(ds.order.values):
            ex = paramres.existence(int(n), 7, system=str(name), duty="1/3", digits=15)
            first = next(t for t in ex.thresholds if t.appears)
            assert not [u for u in ex.undecided if u[0] < first.enclosure[0]]
            here = ds.isel(system=s, duty=0, Q=q7, order=o)
            assert str(here.threshold_text.values) == first.text()
            lo, hi = first.enclosure
            assert float(here.threshold_min) <= lo and float(here.threshold_max) >= hi
            seen.add(str(here.threshold_text.values))
    assert len(seen) == 4  # torsion's thresholds differ from the pendulum's at D = 1/3
    # no friction: no threshold, NaN and empty text
    none = ds.isel(Q=list(ds.Q.values).index(math.inf))
    assert np.all(np.isnan(none.threshold.values))
    assert all(str(t) == "" for t in none.threshold_text.values.ravel())


def test_table_jobs_runs_on_the_engine(client):
    ms = [Fraction(1, 10), Fraction(3, 10)]
    here = rows([1, 2], ms, None, "exact", 20)
    on_cluster = rows([1, 2], ms, None, "exact", 20, jobs=2, scheduler=client)
    assert here == on_cluster


def test_netcdf_opens_with_netcdf4_and_h5netcdf(full):
    netCDF4 = pytest.importorskip("netCDF4")
    path, ds = full
    a = xr.open_dataset(path, engine="netcdf4")
    b = xr.open_dataset(path, engine="h5netcdf")
    for name in ("lower", "upper", "growth", "lower_text", "threshold"):
        assert np.array_equal(a[name].values, b[name].values, equal_nan=a[name].dtype.kind == "f")
        assert np.array_equal(a[name].values, ds[name].values, equal_nan=a[name].dtype.kind == "f")
    for key in ("paramres_version", "command", "digits", "method", "date_created"):
        assert key in a.attrs
    assert a.lower.attrs["units"] == "1" and "long_name" in a.lower.attrs
    with netCDF4.Dataset(path) as raw:  # the C library reads it too
        assert raw.variables["lower_text"][0, 0, 0, 0, 0] == str(
            ds.lower_text.values[0, 0, 0, 0, 0]
        )
    a.close()
    b.close()


class Stop(Exception):
    pass


def test_interrupted_zarr_resumes_to_the_same_dataset(client, full, tmp_path):
    path = tmp_path / "a.zarr"
    seen = []

    def stop_after_three(kind, index):
        seen.append((kind, index))
        if len(seen) == 3:
            raise Stop

    args = {"Q": Q, "T": T, "digits": DIGITS, "output": path, "scheduler": client}
    args["edge_chunk"] = 2
    with pytest.raises(Stop):
        atlas(ORDERS, M, on_chunk=stop_after_three, **args)
    partial = xr.open_zarr(path)
    done = int(partial.edges_done.sum() + partial.growth_done.sum() + partial.thresholds_done.sum())
    assert done == 3
    # another request is refused on this store: a store never changes a result
    with pytest.raises(InputError, match="another request"):
        atlas(ORDERS, M, **{**args, "digits": DIGITS + 1})
    resumed_chunks = []
    ds = atlas(ORDERS, M, on_chunk=lambda k, i: resumed_chunks.append((k, i)), **args)
    assert not set(resumed_chunks) & set(seen)  # the done chunks were skipped
    ref = full[1]
    req = request(ORDERS, M, Q=Q, T=T, digits=DIGITS, edge_chunk=2)
    for kind, tasks in (
        ("edges", req.edge_tasks()),
        ("growth", req.growth_tasks()),
        ("thresholds", req.threshold_tasks()),
    ):
        flags = ds[f"{kind}_done"].values
        assert all(flags[idx] == 1 for idx in tasks) and int(flags.sum()) == len(tasks)
    assert not any(name.endswith("_done") for name in ref.data_vars)  # netCDF: complete
    for name in ref.data_vars:
        a, b = ds[name].values, ref[name].values
        assert np.array_equal(a, b, equal_nan=a.dtype.kind == "f"), name


def test_serial_and_api_lazy(tmp_path):
    import paramres

    ds = paramres.atlas(1, "0.2:0.2:0.1", digits=15, workers=1, output=tmp_path / "s.zarr")
    assert ds.lower.chunks is not None  # opened lazily from the store
    assert (
        str(ds.lower_text.values[0, 0, 0, 0, 0]) == boundary(1, "0.2", digits=15).as_json()["lower"]
    )


# ------------------------------------------------------------------------------------------------
# bad input: exit 2, one line, nothing written


@pytest.mark.parametrize(
    "extra, needle",
    [
        (["--output", "{tmp}/a.csv"], "extension"),
        (["--output", "/proc/x.zarr"], "cannot be written"),
        (["--output", "/proc/x.nc"], "cannot be written"),
        (["--output", "{tmp}/a.nc", "--scheduler", "tcp://127.0.0.1:1"], "no dask scheduler"),
        (["--output", "{tmp}/a.zarr", "--scheduler", "tcp://127.0.0.1:1"], "no dask scheduler"),
        (["--output", "{tmp}/a.nc", "--workers", "0"], "--workers 0"),
        (["--output", "{tmp}/a.nc", "--workers", "2", "--scheduler", "x:1"], "exclude"),
        (["--output", "{tmp}/a.nc", "--system", "custom"], "custom"),
        (["--output", "{tmp}/a.nc", "--Q", "7,-1"], "quality factor"),
        (["--output", "{tmp}/a.nc", "--duty", "1/2,1"], "duty"),
        (["--output", "{tmp}/a.nc", "--T", "0:1:0.1"], "T range"),
    ],
)
def test_bad_input(extra, needle, tmp_path, capsys):
    argv = ["atlas", "--orders", "1", "--m", "0.1:0.2:0.1", "--digits", "15"]
    argv += [a.replace("{tmp}", str(tmp_path)) for a in extra]
    code = main(argv)
    out, err = capsys.readouterr()
    assert code == 2, err
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("paramres: error:") and needle in lines[0]
    assert list(tmp_path.iterdir()) == []


def test_absurd_sizes_are_refused_with_the_estimate(tmp_path, capsys):
    argv = ["atlas", "--orders", "1-10000", "--m", "0.00001:0.99999:0.00001"]
    code = main(argv + ["--output", str(tmp_path / "big.nc")])
    _, err = capsys.readouterr()
    # 10000 orders x 99999 depths: refused before any work, the estimate in the message
    assert code == 2 and "too large" in err and "CPU time" in err and "GB" in err
    code = main(argv + ["--Q", "1,2,3,4,5,6,7,8", "--output", str(tmp_path / "big.zarr")])
    _, err = capsys.readouterr()
    assert code == 2 and "days of CPU time" in err
    assert list(tmp_path.iterdir()) == []


def test_a_store_that_is_not_an_atlas_is_refused(tmp_path, capsys):
    (tmp_path / "x.zarr").mkdir()
    (tmp_path / "x.zarr" / "junk").write_text("not zarr")
    code = main(
        ["atlas", "--orders", "1", "--m", "0.1:0.1:0.1", "--output", str(tmp_path / "x.zarr")]
    )
    _, err = capsys.readouterr()
    assert code == 2 and "paramres: error:" in err
    assert sorted(p.name for p in (tmp_path / "x.zarr").iterdir()) == ["junk"]
