"""Where a sweep's chunks run: processes on this machine, or a Dask cluster.

Each engine yields the rows of each chunk (:func:`~hybrid.sweeps.plan.run_points`) as it finishes.
"""

from __future__ import annotations

import contextlib
import importlib
from collections.abc import Iterator

from hybrid.errors import HybridError
from hybrid.native.binding import workers as cores
from hybrid.simulation import closed_loop
from hybrid.sweeps.plan import _chunks, run_points
from hybrid.sweeps.space import apply
from hybrid.validate import shown

ENGINES = ("local", "dask")


def _local(base, chunks, workers: int):
    """Chunks on a pool of processes, as they finish. Forked where the system can (the workers inherit
    the compiled code already loaded, and a user's script needs no ``__main__`` guard), else spawned
    (each worker loads the cached code once)."""
    if workers == 1:
        for chunk in chunks:
            yield run_points(base, chunk)
        return
    import multiprocessing
    from concurrent.futures import ProcessPoolExecutor, as_completed

    method = "fork" if "fork" in multiprocessing.get_all_start_methods() else "spawn"
    if method == "fork":
        if _PRELOAD[0] is not None:  # an interrupted sweep's: a fork must not copy a thread in an import
            _PRELOAD[0].join()
        _load_loops(base, chunks)
    with ProcessPoolExecutor(max_workers=workers, mp_context=multiprocessing.get_context(method)) as pool:
        futures = [pool.submit(run_points, base, chunk) for chunk in chunks]
        try:
            for f in as_completed(futures):
                yield f.result()
        except BaseException:
            for f in futures:
                f.cancel()
            raise


def _load_loops(base, chunks) -> None:
    """Load, before forking, the compiled loops of the base and of the first run: the workers inherit
    them instead of each loading them again (a fraction of a second each)."""

    for settings in ({}, chunks[0][0][1] if chunks and chunks[0] else {}):
        try:
            closed_loop.prepare(apply(base, settings))
        except Exception:  # noqa: BLE001 - a run's own problem is reported by its row, not here
            pass


#: how long [s] a sweep waits by default to reach a Dask scheduler (``connect_timeout``)
CONNECT_TIMEOUT = 5.0
#: the schemes of a scheduler's address a sweep connects to
SCHEMES = ("tcp", "tls", "ws", "wss")


def check_client(client, engine: str) -> None:
    """``client`` as the documented type, before anything connects: None, a scheduler's address
    (text), or a ``dask.distributed.Client``; and only for ``engine="dask"``."""
    if client is None:
        return
    if engine != "dask":
        raise HybridError(f"client is for engine='dask'; leave it out for engine={engine!r}, or pass engine='dask'")
    if isinstance(client, str):
        _check_address(client)
        return
    try:
        from dask.distributed import Client
    except ImportError:
        raise HybridError("engine='dask' needs dask.distributed: pip install 'dask[distributed]'") from None
    if not isinstance(client, Client):
        raise HybridError(f"client must be a dask.distributed.Client or a scheduler's address such as "
                          f"'tcp://127.0.0.1:8786', got {type(client).__name__}")
    if client.status != "running":
        raise HybridError(f"the Dask client is {client.status}; give a connected one, or its scheduler's address")


def _check_address(address: str) -> None:
    """A scheduler's address ``[scheme://]host:port``: refused here, in words, rather than by Dask."""
    usage = f"give [scheme://]host:port with scheme {', '.join(SCHEMES)}, e.g. 'tcp://127.0.0.1:8786'"
    scheme, sep, rest = address.strip().rpartition("://")
    host, _, port = rest.rpartition(":")
    if (sep and scheme not in SCHEMES) or not host or not port.isdigit() or not 0 < int(port) < 65536 \
            or any(c.isspace() for c in rest):
        raise HybridError(f"the Dask scheduler address {shown(address, 80)} is not one; {usage}")


def _connect(client, workers: int, timeout: float):
    """``(client, own)``: the given client, a new one to the address given, or one of a new local
    cluster; every failure a HybridError saying how long it waited."""
    try:
        from dask.distributed import Client, LocalCluster
    except ImportError:
        raise HybridError("engine='dask' needs dask.distributed: pip install 'dask[distributed]'") from None
    if client is not None and not isinstance(client, str):
        return client, False
    try:
        if client is None:
            cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None)
            try:
                return Client(cluster, timeout=timeout), True
            except BaseException:
                cluster.close()
                raise
        return Client(client, timeout=timeout), True
    except HybridError:
        raise
    except Exception as exc:  # noqa: BLE001 - Dask raises OSError, ValueError, TimeoutError and its own
        where = "a local Dask cluster" if client is None else f"the Dask scheduler at {client}"
        raise HybridError(f"could not reach {where} within {timeout:g} s (connect_timeout); check that it runs "
                          f"and the address, or raise connect_timeout\n  {type(exc).__name__}: {exc}") from None


def _dask(base, chunks, client, workers: int, timeout: float = CONNECT_TIMEOUT):
    """Chunks as Dask tasks (retried when a worker dies), as they finish."""
    from dask.distributed import as_completed

    with dask_client(client, workers, timeout) as client:
        try:
            base_future = client.scatter(base, broadcast=True, timeout=timeout)
            futures = client.map(run_points, [base_future] * len(chunks), chunks, pure=False, retries=3)
        except Exception as exc:  # noqa: BLE001 - a lost or refusing scheduler, in Dask's words below
            raise HybridError(f"the Dask scheduler did not take the sweep within {timeout:g} s (connect_timeout); "
                              f"check the cluster\n  {type(exc).__name__}: {exc}") from None
        for f in as_completed(futures):
            try:
                rows = f.result()
            except Exception as exc:  # noqa: BLE001 - run_points makes every run a row: this is the cluster's
                raise HybridError(f"a Dask task of the sweep failed ({type(exc).__name__}); finished chunks are "
                                  f"kept with out=, run it again to resume\n  {exc}") from None
            yield rows


def run_batch(base, todo: list[tuple[int, dict]], *, workers: int | None = None, client=None,
              timeout: float = CONNECT_TIMEOUT) -> list[dict]:
    """The rows of the runs ``todo`` (``(index, settings)``, settings applied to ``base`` as a sweep applies
    them) in the order given, run as one batch: in chunks on this machine's processes (``workers``, default
    every core), or on the Dask cluster of ``client`` (a connected ``dask.distributed.Client``, left open:
    :func:`dask_client`). Every run is a row, as in a sweep (:func:`~hybrid.sweeps.plan.run_points`)."""
    if not todo:
        return []
    workers = max(1, min(workers or cores(), len(todo)))
    chunks = _chunks(todo, workers)
    results = _local(base, chunks, workers) if client is None else _dask(base, chunks, client, workers, timeout)
    rows = {int(row["run"]): row for chunk in results for row in chunk}
    return [rows[index] for index, _ in todo]


@contextlib.contextmanager
def dask_client(client, workers: int, timeout: float = CONNECT_TIMEOUT) -> Iterator:
    """A connected Dask client for many batches (:func:`run_batch`): ``client`` itself, one to the scheduler
    at the address ``client``, or one of a new local cluster of ``workers`` processes for None; those made
    here are closed at the end."""
    client, own = _connect(client, workers, timeout)
    try:
        yield client
    finally:
        if own:
            cluster = client.cluster
            client.close()
            if cluster is not None:
                cluster.close()


#: the thread loading pandas during a sweep, if any (a later sweep waits for it before it forks)
_PRELOAD: list = [None]


def _preload_pandas() -> None:
    try:
        importlib.import_module("pandas")
    except ImportError:  # said where the table needs it, in the sweep's own thread
        pass
