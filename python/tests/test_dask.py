"""halfplane.dask on a real two-process LocalCluster equals the in-process batch."""

from __future__ import annotations

import pandas as pd
import pytest

import halfplane
from test_batch import mixed_table

dd = pytest.importorskip("dask.dataframe", reason="the dask extra is not installed")
distributed = pytest.importorskip("distributed")


def test_dask_on_a_local_cluster_equals_the_serial_batch():
    import halfplane.dask as hdask

    table = mixed_table(6_000, seed=3)
    serial = halfplane.steady_batch(table)
    with distributed.LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None
    ) as cluster, distributed.Client(cluster):
        lazy = hdask.steady_batch(dd.from_pandas(table, npartitions=4))
        assert list(lazy.columns) == halfplane.STEADY_COLUMNS
        computed = lazy.compute()
    assert len(computed) == len(serial)
    # Dask may store text as its own string dtype; the values must be identical.
    pd.testing.assert_frame_equal(
        computed.astype({"regime": object, "error": object}),
        serial,
        check_exact=True,
    )


def test_meta_has_the_batch_columns_and_dtypes():
    import halfplane.dask as hdask

    meta = hdask.meta()
    out = halfplane.steady_batch(mixed_table(5))
    assert list(meta.columns) == list(out.columns)
    assert list(meta.dtypes) == list(out.dtypes)
