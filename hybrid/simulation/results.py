"""The result of a run: time series, units, metrics; saved and loaded atomically."""

from __future__ import annotations

import json
import zipfile
import zlib
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from hybrid import files
from hybrid.errors import HybridError
from hybrid.experiments.experiment import Experiment
from hybrid.plants.planar import planar_record
from hybrid.simulation.limits import limit_violations
from hybrid.stability.analysis import stability
from hybrid.validate import checked_keywords


@checked_keywords
@dataclass
class SimulationResult:
    """Time series of one run and its metrics: what :func:`~hybrid.simulate` returns.

    One row per integration step (``integration_step`` apart, ``t`` from 0 to the experiment's
    ``duration``); the torque is held over each control sample. Units: ``t`` [s], ``q`` [rad] (m on
    a prismatic joint), ``qdot`` [rad/s], ``tau`` [N m] (N), forces [N], speeds [m/s], lengths [m].
    Points, forces and normals are in base axes; task quantities (``v_t``, ``Fc_n``, ...) in the task
    frame ``R(r)`` at the arm tip. The plant's columns are named in ``record``; the properties below
    read the usual ones by name.

    Parameters
    ----------
    experiment : Experiment
        The run's settings.
    t : numpy.ndarray
        The times [s], one per row.
    state : numpy.ndarray
        The plant's state, one row per time, its columns ``record["state"]``: the joint positions
        ``q``, the joint velocities ``q'``, then the sensor tip's position ``s`` [m] and velocity
        ``s'`` [m/s] (base axes).
    tau : numpy.ndarray
        The joint torques [N m, or N on a prismatic joint], one row per time.
    outputs : numpy.ndarray
        What the plant records besides its state, one row per time, its columns ``record["outputs"]``
        (the arm tip ``r``, its task velocities, the measured force ``F_c`` in base and task axes, the
        sensor tip, the penetration, the contact's normal force ``N``, ...): read one by name with
        :meth:`output`.
    force_reference : numpy.ndarray
        The force reference ``F_d(t)`` [N] at each time.
    speed_reference : numpy.ndarray
        The speed reference ``v_d(t)`` [m/s] along ``t1`` at each time.
    metrics : dict
        The run's metrics by name (conventions §8: :func:`~hybrid.metrics`, with the experiment's
        reference steps); empty by default.
    record : dict
        The plant's record: the names and units of the state's and the outputs' columns (``state``,
        ``state_units``, ``outputs``, ``output_units``) and the number of joints ``nq``; default the
        planar arm's plant's.
    normal_estimate : numpy.ndarray, optional
        The controller's estimate of the surface's unit normal (an :class:`~hybrid.EstimatedSurface`),
        one row of 3 per control sample, base axes, after the sample; None (the default) when the
        controller is told the surface.

    Examples
    --------
    A 50 ms run of the paper's experiment, pressing with 10 N from the start:

    >>> import hybrid
    >>> experiment = hybrid.paper_experiment(duration=0.05)
    >>> result = hybrid.simulate(experiment)
    >>> # 0.05 s in steps of 0.1 ms; two joints
    >>> result.t.shape, result.q.shape
    ((501,), (501, 2))
    >>> # [N]
    >>> (round(float(result.force_normal[-1]), 1),
    ...  float(result.force_reference[-1]))
    (9.9, 10.0)
    >>> result.record["outputs"][:4]
    ('r_x', 'r_y', 'v_t', 'v_n')
    >>> result.metrics["contact_losses"]
    0
    """

    experiment: Experiment
    t: np.ndarray
    state: np.ndarray
    tau: np.ndarray
    outputs: np.ndarray
    force_reference: np.ndarray
    speed_reference: np.ndarray
    metrics: dict = field(default_factory=dict)
    #: the plant's record: names and units of the state and output columns, number of joints
    record: dict = field(default_factory=planar_record)
    #: a controller's estimate of the normal (:class:`~hybrid.EstimatedSurface`), one row per control sample
    #: (base axes, after the sample); None when the controller is told the surface
    normal_estimate: np.ndarray | None = None

    @property
    def sample_t(self) -> np.ndarray:
        """The control samples' times [s]."""
        return np.arange(self.experiment.n_samples) * self.experiment.sample_time

    @property
    def true_normal(self) -> np.ndarray:
        """The true surface's normal at the sensor tip at each control sample (base axes, 3 columns;
        the planar arm's lifted into its plane)."""
        exp, names = self.experiment, self.record["outputs"]
        tip = [names.index(c) for c in ("s_x", "s_y", "s_z") if c in names]
        rows = self.outputs[::exp.steps_per_sample][:exp.n_samples, tip]
        geometry = exp.section or exp.surface
        normals = np.array([geometry.normal_at(p) for p in rows])
        return np.pad(normals, ((0, 0), (0, 3 - normals.shape[1])))

    @property
    def normal_angle_error_deg(self) -> np.ndarray | None:
        """The angle between the estimated and the true normal at each control sample [deg]; None
        without an estimate."""
        if self.normal_estimate is None:
            return None
        cos = np.einsum("ij,ij->i", self.normal_estimate, self.true_normal)
        return np.degrees(np.arccos(np.clip(cos, -1.0, 1.0)))

    @property
    def predicted_stable(self) -> bool:
        """Whether the run's sampled loops were predicted stable (:func:`hybrid.stability`); False only for
        a run with ``allow_unstable=True`` (others are refused when they are not)."""
        return stability(self.experiment, margins=False).stable

    @property
    def limit_violations(self) -> dict:
        """Where the run left the robot's joint limits: ``{kind: LimitViolation}`` for each of
        ``"position"``, ``"velocity"``, ``"effort"`` it left (empty: within them all), from the
        recorded joints and torques (:mod:`hybrid.simulation.limits`)."""
        return limit_violations(self.experiment.robot, self.t, self.q, self.qdot, self.tau)

    @property
    def UNITS(self) -> dict:  # noqa: N802 (a table, as before)
        """The units of each array, by its name (``"t"``, ``"state"``, ``"tau"``, ...): a column's, or its
        columns' in order, as text; what :meth:`save` writes beside the arrays."""
        rec = self.record
        return {"t": "s", "state": ", ".join(rec["state_units"]), "tau": "N m",
                "force_reference": "N", "speed_reference": "m/s", "outputs": ", ".join(rec["output_units"])}

    @property
    def q(self):
        """The joint positions ``q`` [rad, or m on a prismatic joint], one row per time."""
        return self.state[:, 0:self.record["nq"]]

    @property
    def qdot(self):
        """The joint velocities ``q'`` [rad/s, or m/s on a prismatic joint], one row per time."""
        return self.state[:, self.record["nq"]:2 * self.record["nq"]]

    def output(self, name: str) -> np.ndarray:
        """A column of the plant's outputs, by name.

        Parameters
        ----------
        name : str
            One of ``result.record["outputs"]`` (its unit the same place in ``record["output_units"]``):
            e.g. ``"r_x"`` (the arm tip's x [m]), ``"v_t"``, ``"Fc_n"``, ``"penetration"``, ``"N"``.

        Returns
        -------
        numpy.ndarray
            The column, one value per time.

        Raises
        ------
        HybridError
            A name the plant does not record (the message lists those it does).
        """
        try:
            return self.outputs[:, self.record["outputs"].index(name)]
        except ValueError:
            names = ", ".join(self.record["outputs"])
            raise HybridError(f"the plant records no {name!r}; it records {names}") from None

    @property
    def force_normal(self):
        """The normal force measured by the sensor, ``(R(r) F_c)_n`` [N] (positive: pressing), per time."""
        return self.output("Fc_n")

    @property
    def force_tangential(self):
        """The measured force along the task axis ``t1``, ``(R(r) F_c)_t`` [N], where the friction
        shows, per time."""
        return self.output("Fc_t")

    @property
    def velocity_tangential(self):
        """The arm tip's speed along the task axis ``t1``, ``(R(r) r')_t`` [m/s], per time."""
        return self.output("v_t")

    @property
    def velocity_normal(self):
        """The arm tip's velocity along the normal ``n`` (away from the surface), ``(R(r) r')_n``
        [m/s], per time."""
        return self.output("v_n")

    @property
    def penetration(self):
        """The sensor tip's penetration into the surface, ``delta`` [m] (positive in contact, where the
        contact's penalty acts on it), per time."""
        return self.output("penetration")

    @property
    def contact_force(self):
        """The surface's normal force on the sensor tip, ``N = max(0, k_e delta + d_e delta')`` while it
        penetrates, else 0 [N] (positive: in contact), per time."""
        return self.output("N")

    def plot(self, title: str | None = None):
        """The run as a matplotlib figure: tangential speed [m/s] and normal force [N] against their
        references over time [s]; for a 3-D run also the sensor tip's deviation from the desired path
        across it [mm] and its penetration [mm] (:func:`hybrid.plots.plot_result`).

        Parameters
        ----------
        title : str, optional
            The figure's title; default the scheme's name and "one run".

        Returns
        -------
        matplotlib.figure.Figure
            The figure: nothing is shown or written (save it with ``fig.savefig("run.pdf")``).
        """
        from hybrid.plots import plot_result

        return plot_result(self, title)

    def animate(self, every: int | None = None, out: str | Path | None = None, *, fps: float | None = None,
                overwrite: bool = False, force_scale: float | None = None, title: str | None = None):
        """The arm doing the task, as a matplotlib animation (:func:`hybrid.animation.animate`).

        Each picture shows, at a control sample, the links through the joint origins, the surface, the
        sensor tip's path so far, the recorded contact force as an arrow and the task frame's axes at
        the tip.

        Parameters
        ----------
        every : int, optional
            A picture every this many control samples, and one at the run's end; default about 60
            pictures in all.
        out : str or pathlib.Path, optional
            Also write the animation there, atomically: a ``.gif`` (an ``.mp4`` needs ffmpeg). None
            (the default): nothing is written.
        fps : float, optional
            Pictures per second; default real time, within 1 to 30.
        overwrite : bool
            Whether an existing ``out`` is replaced (default False: refused).
        force_scale : float, optional
            The force arrow's length per newton [m/N]; default the run's largest recorded contact
            force drawn 0.1 m long.
        title : str, optional
            The figure's title.

        Returns
        -------
        matplotlib.animation.FuncAnimation
            The animation (its figure stays open: in a notebook, show it with
            ``IPython.display.HTML(anim.to_jshtml())``).

        Raises
        ------
        HybridError
            An ``every``, ``fps`` or ``force_scale`` that is not positive, an ``out`` that is not a
            ``.gif`` or ``.mp4`` name (or an ``.mp4`` without ffmpeg), or an existing ``out`` without
            ``overwrite``.
        """
        from hybrid.animation import animate

        return animate(self, every, out, fps=fps, overwrite=overwrite, force_scale=force_scale, title=title)

    def view(self, every: int | None = None, *, force_scale: float | None = None, fps: float | None = None,
             title: str | None = None, out: str | Path | None = None, overwrite: bool = False):
        """The arm doing the task as an interactive 3-D figure for the browser (:func:`hybrid.view`).

        The pictures :meth:`animate` draws, with a play button and a slider. Needs plotly (``pip install
        'hybrid-decoupling[view]'``).

        Parameters
        ----------
        every : int, optional
            A frame every this many control samples, and one at the run's end; default about 60 frames.
        force_scale : float, optional
            The force arrow's length per newton [m/N]; default the run's largest recorded contact force
            drawn 0.1 m long.
        fps : float, optional
            Frames per second when played; default real time, within 1 to 30.
        title : str, optional
            The figure's title.
        out : str or pathlib.Path, optional
            Also write the figure there, atomically, as one ``.html`` file that opens offline (plotly.js
            inside).
        overwrite : bool
            Whether an existing ``out`` is replaced (default False: refused).

        Returns
        -------
        plotly.graph_objects.Figure
            The figure, one animation frame per chosen sample.
        """
        from hybrid.view3d import view

        return view(self, every, force_scale=force_scale, fps=fps, title=title, out=out, overwrite=overwrite)

    def save(self, path: str | Path, overwrite: bool = False) -> Path:
        """Write the run to an ``.npz`` file: every array, the units, the plant's record, the metrics and
        the experiment's settings (:meth:`Experiment.to_dict`); :meth:`load` reads it back.

        The file is written atomically: whole, or not at all.

        Parameters
        ----------
        path : str or pathlib.Path
            The file name; ``.npz`` is added when it does not end so.
        overwrite : bool
            Whether an existing file is replaced (default False: refused).

        Returns
        -------
        pathlib.Path
            The path written.

        Raises
        ------
        HybridError
            An existing file without ``overwrite``, a folder, or a place that cannot be written.
        """
        path = files.output_path(path)
        if path.suffix != ".npz":
            path = path.with_name(path.name + ".npz")

        def write(tmp: Path) -> None:
            with open(tmp, "wb") as f:  # a file object: NumPy adds no suffix to it
                np.savez_compressed(
                    f, t=self.t, state=self.state, tau=self.tau, outputs=self.outputs,
                    force_reference=self.force_reference, speed_reference=self.speed_reference,
                    output_names=np.array(self.record["outputs"]), units=json.dumps(self.UNITS),
                    record=json.dumps(self.record),
                    experiment=json.dumps(self.experiment.to_dict()), metrics=json.dumps(self.metrics),
                    **({} if self.normal_estimate is None else {"normal_estimate": self.normal_estimate}))

        return files.write_with(path, write, overwrite)

    @classmethod
    def load(cls, path: str | Path) -> SimulationResult:
        """The result :meth:`save` wrote.

        Parameters
        ----------
        path : str or pathlib.Path
            The ``.npz`` file.

        Returns
        -------
        SimulationResult
            The run, its experiment rebuilt from its settings (:meth:`Experiment.from_dict`).

        Raises
        ------
        HybridError
            A missing, truncated or foreign file, or one whose arrays do not have the shapes of a run.
        """
        try:
            files.regular_file(path, "saved result")  # before np.load opens it: a FIFO would block it
        except HybridError as exc:
            raise HybridError(f"{path!s:.200} is not a readable saved hybrid result ({str(exc).partition('; ')[0]}); "
                              "give a file written by SimulationResult.save") from None
        try:
            with np.load(path, allow_pickle=False) as z:
                arrays = {k: z[k] for k in ("t", "state", "tau", "outputs", "force_reference", "speed_reference")}
                settings = json.loads(str(z["experiment"]))
                experiment = Experiment.from_dict(settings)
                metrics = json.loads(str(z["metrics"]))
                # a file from before the record was saved holds a paper run: its record is the paper plant's
                record = _record(json.loads(str(z["record"]))) if "record" in z.files else planar_record()
                normals = z["normal_estimate"] if "normal_estimate" in z.files else None
            n = len(arrays["t"])
            shapes = {"t": (n,), "state": (n, len(record["state"])), "tau": (n, record["nq"]),
                      "outputs": (n, len(record["outputs"])), "force_reference": (n,), "speed_reference": (n,)}
            wrong = [k for k, shape in shapes.items() if arrays[k].shape != shape]
            if normals is not None and normals.shape != (experiment.n_samples, 3):
                wrong.append("normal_estimate")
            if wrong or n == 0 or not np.isfinite(arrays["t"]).all() or not isinstance(metrics, dict):
                raise ValueError(f"arrays {', '.join(wrong) or 't'} do not have the shapes of a run")
            return cls(experiment, arrays["t"], arrays["state"], arrays["tau"], arrays["outputs"],
                       arrays["force_reference"], arrays["speed_reference"], metrics, record, normals)
        except (OSError, KeyError, ValueError, EOFError, zipfile.BadZipFile, zlib.error, TypeError,
                AttributeError) as exc:
            why = getattr(exc, "strerror", None) or f"{type(exc).__name__}: {exc}"
            raise HybridError(f"{path} is not a readable saved hybrid result ({why:.120}); "
                              "save it again with SimulationResult.save") from None

    def save_csv(self, path: str | Path, overwrite: bool = False) -> Path:
        """Write the time series as CSV, one row per time, each column's unit in its name.

        The columns: ``t_s``, the joint positions (``q1_rad``, ...), the torques (``tau1_Nm``, ...), the
        references (``force_reference_N``, ``speed_reference_m_per_s``), then every output of the
        plant (``v_t_m_per_s``, ``Fc_n_N``, ...). Written atomically: whole, or not at all.

        Parameters
        ----------
        path : str or pathlib.Path
            The file name (written as given).
        overwrite : bool
            Whether an existing file is replaced (default False: refused).

        Returns
        -------
        pathlib.Path
            The path written.

        Raises
        ------
        HybridError
            An existing file without ``overwrite``, a folder, or a place that cannot be written.
        """
        path = files.output_path(path)
        joint_units = self.record["state_units"][:self.record["nq"]]
        cols = {"t_s": self.t, **{f"q{j + 1}_{u}": self.q[:, j] for j, u in enumerate(joint_units)},
                **{f"tau{j + 1}_{'Nm' if u == 'rad' else 'N'}": self.tau[:, j] for j, u in enumerate(joint_units)},
                "force_reference_N": self.force_reference, "speed_reference_m_per_s": self.speed_reference}
        units = dict(zip(self.record["outputs"], self.record["output_units"]))
        cols.update({f"{n}_{units[n].replace('/', '_per_').replace(' ', '')}": self.output(n)
                     for n in self.record["outputs"]})
        return files.write_with(path, lambda tmp: np.savetxt(
            tmp, np.column_stack(list(cols.values())), delimiter=",", header=",".join(cols), comments="",
            fmt="%.10g"), overwrite)


def _record(data) -> dict:
    """A plant's record as :meth:`SimulationResult.save` wrote it (names and units as tuples)."""
    if not isinstance(data, dict):
        raise ValueError("the record is not a table")
    return {k: v if k == "nq" else tuple(v) for k, v in data.items()}
