"""Rerun: the live stream of a running trial (:class:`RerunLog`, a sink) and the writer both it and the
replay use (:class:`RerunView`: scene, time series, events, default layout).

Targets (``boatland run --rerun TARGET``): ``save=PATH.rrd`` (a file), ``serve`` (a gRPC server in this
process that viewers connect to, late viewers get the whole run), ``connect[=URL]`` (push to a viewer
already listening; checked before the run), ``spawn`` (start a native viewer; needs a display). None of
them waits for a viewer that is not there: an absent viewer is an error before the trial starts.

The ``serve`` server and the viewer ``spawn`` starts listen on 127.0.0.1 (this machine only) unless the
caller binds them wider (``bind="0.0.0.0"``, with a warning: Rerun's server has no authentication) —
``rerun.spawn`` itself would start the viewer on every interface (the ``rerun`` command's default bind
is 0.0.0.0), so :func:`spawn_viewer` starts it with ``--bind``. A port already in use is an error
before the trial starts for ``serve`` (Rerun itself would only log it and serve nothing); ``spawn``
connects to the viewer already listening there, as ``rerun.spawn`` does.
"""

from __future__ import annotations

import os
import socket
import sys
import uuid
from pathlib import Path
from urllib.parse import urlparse

import numpy as np

from boatland.errors import BoatlandInputError
from boatland.record.columns import BowElevation, Columns, LandingTracker, settle_row
from boatland.record.mcap_log import columns_from_block, end_event, step_events
from boatland.trial.incidents import IncidentWatch
from boatland.record.scene import COLORS, FENDER_RADIUS, FORCE_SCALE, MODE_COLORS, PATCH_DT, PILE_BOTTOM, PILE_TOP, \
    SERIES, SERIES_LIGHT, Scene, fender_forces, scene_from_trial

__all__ = ["RerunView", "RerunLog", "parse_target", "open_stream", "check_target", "blueprint", "serve_until_interrupted",
           "spawn_viewer", "exposure_warning", "key_moment", "show_moment", "wait_listening", "APPLICATION_ID", "TIMELINE"]

APPLICATION_ID = "boatland"
TIMELINE = "sim_time"
DEFAULT_URL = "rerun+http://127.0.0.1:9876/proxy"
FLUSH_EVERY = 30.0     # [s] of simulated time buffered between sends of the live stream
FENDER_POINT_RADIUS = 0.35   # [m] drawn radius of the contact points, coloured by the contact's state


DEFAULT_BIND, DEFAULT_PORT = "127.0.0.1", 9876


def parse_target(spec: str, *, bind: str = DEFAULT_BIND, port: int = DEFAULT_PORT) -> tuple[str, str | None]:
    """``spawn | serve | connect[=URL] | save=PATH`` → (kind, argument); ``bind`` and ``port`` (of
    ``serve``) are checked too."""
    _check_bind(bind, port)
    kind, _, arg = spec.partition("=")
    if kind in ("spawn", "serve") and not arg:
        return kind, None
    if kind == "connect":
        return kind, arg or DEFAULT_URL
    if kind == "save" and arg:
        return kind, arg
    raise BoatlandInputError(f"--rerun {spec}: expected spawn, serve, connect[=URL] or save=PATH.rrd")


def _check_bind(bind: str, port: int) -> None:
    try:
        infos = socket.getaddrinfo(bind, port, type=socket.SOCK_STREAM, flags=socket.AI_NUMERICHOST)
    except (socket.gaierror, UnicodeError, OverflowError, TypeError):
        raise BoatlandInputError(f"--bind {bind}: not a numeric IP address (e.g. 127.0.0.1, or 0.0.0.0 for "
                                 "every interface)") from None
    if not infos or not 0 < int(port) < 65536:
        raise BoatlandInputError(f"--port {port}: must lie in 1 … 65535")
    if infos[0][0] != socket.AF_INET:      # Rerun 0.41's server sink takes an IPv4 address only
        raise BoatlandInputError(f"--bind {bind}: an IPv4 address is needed (Rerun's server takes no IPv6 "
                                 "address): 127.0.0.1, or 0.0.0.0 for every interface")


def check_port_free(bind: str, port: int) -> None:
    """Refuse a port another process listens on (``--rerun serve``, ``replay --serve``)."""
    family = socket.AF_INET6 if ":" in bind else socket.AF_INET
    with socket.socket(family, socket.SOCK_STREAM) as s:
        s.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)   # as the server does: TIME_WAIT is no conflict
        try:
            s.bind((bind, port))
        except OSError as exc:
            raise BoatlandInputError(f"--port {port}: cannot listen on {bind}:{port} ({exc.strerror or exc}; "
                                     "another viewer or server?); give another --port") from None


def wait_listening(bind: str, port: int, timeout: float = 5.0) -> bool:
    """Whether something accepts connections on ``bind``:``port`` within ``timeout`` s (tried at least once)."""
    import time

    host = "127.0.0.1" if bind in ("0.0.0.0", "") else ("::1" if bind == "::" else bind)
    deadline = time.monotonic() + timeout
    while True:
        try:
            with socket.create_connection((host, port), timeout=0.5):
                return True
        except OSError:
            if time.monotonic() >= deadline:
                return False
            time.sleep(0.05)


def exposure_warning(bind: str, port: int, what: str) -> str | None:
    """The warning a listener on ``bind``:``port`` beyond this machine gets (None on a loopback address)."""
    if _is_loopback(bind):
        return None
    return (f"warning: rerun: {what} on {bind}:{port} without authentication: anyone who can reach this machine "
            "can read the run")


def _warn_if_open(bind: str, port: int, what: str) -> None:
    text = exposure_warning(bind, port, what)
    if text:
        print(text, file=sys.stderr)


#: Seconds to wait for a spawned viewer to accept connections.
SPAWN_TIMEOUT = 20.0


def spawn_viewer(bind: str = DEFAULT_BIND, port: int = DEFAULT_PORT) -> None:
    """Start a native Rerun viewer listening on ``bind``:``port`` (detached: it outlives the run) and wait
    until it accepts connections; a viewer already listening there is used as it is.

    What ``rerun.spawn`` does, but with the listening address: it runs ``rerun --port N`` and the
    ``rerun`` command binds 0.0.0.0 unless told otherwise (``rerun --help``, 0.41), which would open every
    spawned viewer to the network. Same memory limits as ``rerun.spawn`` (75 % for the viewer, 1 GiB for
    its server)."""
    import subprocess

    if wait_listening(bind, port, timeout=0.0):
        return
    _warn_if_open(bind, port, "the spawned viewer listens")
    subprocess.Popen([sys.executable, "-m", "rerun_cli", "--bind", bind, "--port", str(port), "--memory-limit", "75%",
                      "--server-memory-limit", "1GiB"], env={**os.environ, "RERUN_APP_ONLY": "true"},
                     stdin=subprocess.DEVNULL, start_new_session=True)
    if not wait_listening(bind, port, timeout=SPAWN_TIMEOUT):
        raise BoatlandInputError(f"--rerun spawn: the Rerun viewer did not start listening on {bind}:{port} within "
                                 f"{SPAWN_TIMEOUT:g} s (its own messages are above); use --rerun serve, or "
                                 "--rerun save=FILE.rrd")


def _is_loopback(bind: str) -> bool:
    import ipaddress

    try:
        return ipaddress.ip_address(bind).is_loopback
    except ValueError:
        return False


def _check_viewer(url: str) -> None:
    u = urlparse(url)
    host, port = u.hostname or "127.0.0.1", u.port or 9876
    try:
        with socket.create_connection((host, port), timeout=1.0):
            pass
    except OSError:
        raise BoatlandInputError(f"--rerun connect: no Rerun viewer listening at {url} (start one with 'rerun', "
                                 "or use --rerun serve / --rerun save=FILE.rrd)") from None


def blueprint(n_contacts: int = 0, scene: Scene | None = None):
    """The default layout: left, the 3D scene looking at the bow and the landing (``scene.camera()``) above
    the events (wide enough for their text); right, time series — heave and the wave at the bow; roll and
    pitch; each contact's needed and available friction (its normal and friction forces are logged too, one
    click away); thrust; slip distance — each with its legend inside the plot."""
    import rerun.blueprint as rrb

    eye = None
    if scene is not None:
        position, target = scene.camera()
        eye = rrb.EyeControls3D(position=position, look_target=target, eye_up=[0.0, 0.0, 1.0])
    legend = rrb.PlotLegend(corner="LeftTop", visible=True)
    plots = lambda name, *paths: rrb.TimeSeriesView(origin="/plots", contents=list(paths), name=name,  # noqa: E731
                                                    plot_legend=legend)
    fender = [f"/plots/fender/{k}/{q}" for k in range(n_contacts) for q in ("needed", "available")] or ["/plots/fender/**"]
    return rrb.Blueprint(
        rrb.Horizontal(
            rrb.Vertical(
                rrb.Spatial3DView(origin="/world", name="Landing", eye_controls=eye,
                                  line_grid=rrb.LineGrid3D(visible=False),
                                  background=rrb.Background(kind="SolidColor", color=COLORS["sky"])),
                rrb.TextLogView(origin="/events", name="Events"),
                row_shares=[3, 1]),
            rrb.Vertical(
                plots("Heave and wave at the bow [m]", "/plots/motion/heave", "/plots/sea/bow_elevation"),
                plots("Roll, pitch [deg]", "/plots/motion/roll", "/plots/motion/pitch"),
                plots("Friction needed vs available, per contact [kN]", *fender),
                plots("Thrust [kN]", "/plots/loads/thrust"),
                plots("Slip distance from landing [m]", "/plots/slip/**"),
                row_shares=[2, 1.5, 2.5, 1, 1.5]),
            column_shares=[3, 2]),
        collapse_panels=True)


def key_moment(c: Columns, t_from: float = 0.0) -> tuple[float, str]:
    """The moment a replay opens at: the first slip from ``t_from`` (the end of the settling) on, else the
    most loaded moment — the largest needed / available friction of any contact — and what it is, in words.

    Returns
    -------
    (float, str)
        Time [s] and e.g. ``"the first slip (contact 0)"`` or ``"the most loaded moment (contact 1 at 87 %
        of its friction)"``; (``t_from``, "the start of the access") when no contact ever carried load.
    """
    rows = np.flatnonzero(c.t >= t_from - 1e-9)
    if not rows.size:
        return float(c.t[0]) if len(c) else 0.0, "the start"
    mode = c.mode[rows]
    slip = np.flatnonzero((mode == 2).any(axis=1))
    if slip.size:
        r = rows[slip[0]]
        return float(c.t[r]), f"the first slip (contact {int(np.argmax(c.mode[r] == 2))})"
    with np.errstate(divide="ignore", invalid="ignore"):
        use = np.where(c.available[rows] > 0, c.needed[rows] / c.available[rows], 0.0)
    if not use.size or not np.nanmax(use) > 0:
        return float(c.t[rows[0]]), "the start of the access"
    i, k = np.unravel_index(np.nanargmax(use), use.shape)
    return float(c.t[rows[i]]), f"the most loaded moment (contact {k} at {use[i, k]:.0%} of its friction)"


def show_moment(url: str, t: float, timeout: float = 10.0) -> bool:
    """Move the time cursor of the viewer at ``url`` to ``t`` [s] on the run's timeline, paused (Rerun's
    experimental ``ViewerClient``; the blueprint has no field for the cursor, Rerun 0.41). Waits up to
    ``timeout`` for the viewer to hold the recording's data there. False, silently, when the viewer cannot be
    driven (another Rerun, a web viewer): the replay is complete either way."""
    import time
    import warnings

    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            from rerun.experimental import ViewerClient

            client = ViewerClient.connect(url)
            deadline = time.monotonic() + timeout
            while True:            # the stream may still be arriving: wait until its timeline reaches t
                state = client.get_state()
                rec = next((r for r in state.recordings if r.store_id == state.active_recording), None)
                line = next((tl for tl in (rec.timelines if rec else ()) if tl.name == TIMELINE), None)
                if line is not None and line.end >= round(t * 1e9) or time.monotonic() > deadline:
                    break
                time.sleep(0.1)
            client.set_time(TIMELINE, duration=t, play_state="paused")
        return True
    except Exception:  # noqa: BLE001 - pointing the viewer is a courtesy; the data is there regardless
        return False


def check_target(target: str, *, bind: str = DEFAULT_BIND, port: int = DEFAULT_PORT) -> tuple[str, str | None]:
    """Parse ``target`` and make sure using it cannot hang: a viewer must be listening for ``connect``,
    a display must exist for ``spawn``, the directory of ``save=PATH`` must exist, the port of ``serve``
    must be free.

    Raises
    ------
    BoatlandInputError
        With what to do instead.
    """
    from pathlib import Path

    kind, arg = parse_target(target, bind=bind, port=port)
    if kind == "serve":
        check_port_free(bind, port)
    if kind == "connect":
        _check_viewer(arg)
    if kind == "spawn" and not (os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY")
                                or sys.platform in ("darwin", "win32")):
        raise BoatlandInputError("--rerun spawn: no display here (neither DISPLAY nor WAYLAND_DISPLAY is set); "
                                 "use --rerun serve, or --rerun save=FILE.rrd and open it elsewhere")
    if kind == "save" and not Path(arg).resolve().parent.is_dir():
        raise BoatlandInputError(f"--rerun save={arg}: the directory {Path(arg).parent} does not exist")
    return kind, arg


def open_stream(target: str, *, recording_id: str | None = None, n_contacts: int = 0, quiet: bool = False,
                bind: str = DEFAULT_BIND, port: int = DEFAULT_PORT, scene: Scene | None = None):
    """A RecordingStream sending to ``target`` (checked with :func:`check_target`), with the default layout
    (its camera on ``scene``'s bow and landing).

    ``bind``, ``port``: where a ``serve`` target, or the viewer ``spawn`` starts, listens (default
    127.0.0.1:9876: this machine only).

    Returns (stream, kind, uri-or-path, file): ``file`` the :class:`RrdFile` of a ``save`` target (None for
    the others)."""
    import rerun as rr

    kind, arg = check_target(target, bind=bind, port=port)
    rec = rr.RecordingStream(APPLICATION_ID, recording_id=recording_id or str(uuid.uuid4()))
    bp = blueprint(n_contacts, scene)
    where, file = arg, None
    if kind == "save":
        file = RrdFile(rec, arg)
    elif kind == "serve":
        _warn_if_open(bind, port, "serving")
        sink = rr.GrpcServerSink(bind_ip=bind, port=port)
        rec.set_sinks(sink, default_blueprint=bp)
        if not wait_listening(bind, port):
            rec.disconnect()
            raise BoatlandInputError(f"--rerun serve: the Rerun server did not start listening on {bind}:{port}")
        where = _proxy_url(bind, port)
        if not quiet:
            print(f"rerun: serving the run on {bind}:{port}: open it with: rerun {where}", file=sys.stderr)
    elif kind == "connect":
        rec.connect_grpc(arg, default_blueprint=bp)
    else:
        spawn_viewer(bind, port)
        where = _proxy_url(bind, port)
        rec.connect_grpc(where, default_blueprint=bp)
    # active too: a viewer keeps the layout it last showed for the application (persisted on disk), which
    # would hide a newer boatland's layout; the user's own changes last until the next run or replay
    rec.send_blueprint(bp, make_active=True, make_default=True)
    return rec, kind, where, file


class RrdFile:
    """A ``.rrd`` recording written by Python from the stream's bytes (Rerun's ``binary_stream``, held in
    memory until :meth:`close`: each read of it is a whole recording with its own footer, so it is read once)
    through :func:`boatland.atomic.atomic_path`.

    Rerun's own file sink logs a failed write and carries on, so a full disk or a file-size limit would
    leave a truncated recording under its name and a run that says "wrote"; here such a failure is an
    ``OSError`` naming the file, and nothing is left under its name.
    """

    def __init__(self, rec, path: str | os.PathLike):
        self.path = Path(path)
        self.stream = rec.binary_stream()
        self.closed = False

    def close(self) -> None:
        """The whole stream, written to the file (once)."""
        from boatland.atomic import atomic_path

        if self.closed:
            return
        self.closed = True
        data = self.stream.read() or b""
        with atomic_path(self.path) as tmp:
            tmp.write_bytes(data)


def _proxy_url(bind: str, port: int) -> str:
    """The URL a viewer on this machine opens for a server listening on ``bind``:``port``."""
    host = "127.0.0.1" if not bind or bind in ("0.0.0.0", "::") or _is_loopback(bind) else bind
    return f"rerun+http://{host}:{port}/proxy"


class RerunView:
    """Writes a trial to a Rerun stream: the static scene once, then columns and events in batches
    (``send_columns``, one call per entity per batch)."""

    def __init__(self, rec, scene: Scene, n_contacts: int):
        self.rec, self.scene, self.nc = rec, scene, n_contacts
        self._sea_next = 0.0

    def static(self) -> None:
        """The scene: hull (antifouling below the waterline, light topsides), monopile, landing tubes from
        their bottom to their top, fender lines, the sea's triangles; the plots' names."""
        import rerun as rr

        rec, sc = self.rec, self.scene
        rec.log("/world", rr.ViewCoordinates.RIGHT_HAND_Z_UP, static=True)
        solid = rr.components.FillMode.Solid
        mx, my, md = sc.monopile
        if md > 0:
            rec.log("/world/monopile", rr.Cylinders3D(
                lengths=[PILE_TOP - PILE_BOTTOM], radii=[md / 2], centers=[[mx, my, 0.5 * (PILE_TOP + PILE_BOTTOM)]],
                colors=[COLORS["monopile"]], fill_mode=solid), static=True)
        if sc.struts:
            s = np.asarray(sc.struts, float)
            rec.log("/world/landing/struts", rr.Cylinders3D(
                lengths=s[:, 4] - s[:, 3], radii=s[:, 2] / 2,
                centers=np.column_stack([s[:, 0], s[:, 1], 0.5 * (s[:, 3] + s[:, 4])]), colors=[COLORS["tube"]],
                fill_mode=solid), static=True)
        rec.log("/world/vessel/hull", rr.Mesh3D(vertex_positions=sc.hull_vertices, triangle_indices=sc.hull_triangles,
                                                vertex_colors=sc.hull_colors), static=True)
        if len(sc.fender_points):
            rec.log("/world/vessel/fender_line", rr.LineStrips3D(sc.fender_lines, radii=FENDER_RADIUS,
                                                                 colors=[COLORS["fender"]]), static=True)
            # positions and radii static; the colours are temporal (static data would shadow them)
            rec.log("/world/vessel/fender", rr.Points3D.from_fields(positions=sc.fender_points,
                                                                    radii=FENDER_POINT_RADIUS), static=True)
        if sc.components is not None:
            X, Y, tri = sc.patch_grid()
            # the triangles and colour static; the vertices are temporal (:meth:`_sea`): static data
            # would shadow them
            rec.log("/world/sea", rr.Mesh3D.from_fields(triangle_indices=tri, albedo_factor=COLORS["sea"]),
                    static=True)
        styles = {"/plots/motion/heave": ("heave [m]", SERIES[0]),
                  "/plots/sea/bow_elevation": ("wave at the bow [m]", SERIES_LIGHT[0]),
                  "/plots/motion/roll": ("roll [deg]", SERIES[2]), "/plots/motion/pitch": ("pitch [deg]", SERIES[4]),
                  "/plots/loads/thrust": ("thrust [kN]", SERIES[5])}
        for k in range(self.nc):
            pair = (SERIES[k % len(SERIES)], SERIES_LIGHT[k % len(SERIES)])
            styles[f"/plots/fender/{k}/needed"] = (f"contact {k} needed", pair[0])
            styles[f"/plots/fender/{k}/available"] = (f"contact {k} available", pair[1])
            styles[f"/plots/fender/{k}/friction"] = (f"contact {k} friction", pair[0])
            styles[f"/plots/fender/{k}/normal"] = (f"contact {k} normal", SERIES[7])
            styles[f"/plots/slip/{k}"] = (f"contact {k}", pair[0])
        for path, (name, color) in styles.items():
            rec.log(path, rr.SeriesLines(names=name, colors=[color]), static=True)

    def columns(self, c: Columns) -> None:
        import rerun as rr

        if not len(c):
            return
        rec = self.rec
        idx = [rr.TimeColumn(TIMELINE, duration=c.t)]
        send = lambda path, values: rr.send_columns(path, indexes=idx, recording=rec,  # noqa: E731
                                                    columns=rr.Scalars.columns(scalars=np.asarray(values, float)))
        rr.send_columns("/world/vessel", indexes=idx, recording=rec,
                        columns=rr.Transform3D.columns(translation=c.translation, quaternion=c.quaternion))
        send("/plots/motion/heave", c.x[:, 2])
        send("/plots/motion/roll", np.degrees(c.x[:, 3]))
        send("/plots/motion/pitch", np.degrees(c.x[:, 4]))
        for k in range(self.nc):
            send(f"/plots/fender/{k}/normal", c.fn[:, k] / 1e3)
            send(f"/plots/fender/{k}/friction", np.hypot(c.ft[:, k, 0], c.ft[:, k, 1]) / 1e3)
            send(f"/plots/fender/{k}/needed", c.needed[:, k] / 1e3)
            send(f"/plots/fender/{k}/available", c.available[:, k] / 1e3)
            send(f"/plots/slip/{k}", c.slip[:, k])
        send("/plots/loads/thrust", c.thrust / 1e3)
        send("/plots/sea/bow_elevation", c.eta_bow)
        if self.nc:
            colors = MODE_COLORS[c.mode.ravel()]
            rr.send_columns("/world/vessel/fender", indexes=idx, recording=rec,
                            columns=rr.Points3D.columns(colors=colors).partition(np.full(len(c), self.nc)))
            self._arrows(c, idx, colors)
        self._sea(float(c.t[-1]))

    def _arrows(self, c: Columns, idx, colors) -> None:
        """The fender forces on the vessel, per step: from each contact point its normal force and its
        friction, 1 m per 10 kN (:data:`~boatland.record.scene.FORCE_SCALE`), coloured by the contact's state."""
        import rerun as rr

        origin, normal, friction = fender_forces(self.scene, c.x, c.fn, c.ft)
        n = len(c)
        vec = np.stack([normal, friction], axis=2).reshape(n, -1, 3) * FORCE_SCALE
        org = np.repeat(origin, 2, axis=1)
        col = np.repeat(colors.reshape(n, self.nc, 4), 2, axis=1)
        radii = np.tile([0.09, 0.06], (n, self.nc))                    # friction arrows thinner
        m = 2 * self.nc
        rr.send_columns("/world/fender_forces", indexes=idx, recording=self.rec,
                        columns=rr.Arrows3D.columns(vectors=vec.reshape(-1, 3), origins=org.reshape(-1, 3),
                                                    colors=col.reshape(-1, 4), radii=radii.ravel())
                        .partition(np.full(n, m)))

    def _sea(self, t_last: float) -> None:
        """Sea-patch frames on the grid k·PATCH_DT up to ``t_last``."""
        import rerun as rr

        if self.scene.components is None:
            return
        k0 = int(np.ceil(self._sea_next / PATCH_DT - 1e-9))
        k1 = int(np.floor(t_last / PATCH_DT + 1e-9))
        if k1 < k0:
            return
        t = np.arange(k0, k1 + 1) * PATCH_DT
        eta = self.scene.sea_frames(t)
        X, Y, _ = self.scene.patch_grid()
        P = len(X)
        pos = np.empty((len(t), P, 3), np.float32)
        pos[:, :, 0], pos[:, :, 1], pos[:, :, 2] = X, Y, eta
        rr.send_columns("/world/sea", indexes=[rr.TimeColumn(TIMELINE, duration=t)], recording=self.rec,
                        columns=rr.Mesh3D.columns(vertex_positions=pos.reshape(-1, 3)).partition(np.full(len(t), P)))
        self._sea_next = (k1 + 1) * PATCH_DT

    def events(self, events: list[tuple[int, str, str]]) -> None:
        """``(t_ns, level, text)`` events to ``/events``."""
        import rerun as rr

        if not events:
            return
        t = np.array([e[0] for e in events], np.int64).astype("timedelta64[ns]")
        rr.send_columns("/events", indexes=[rr.TimeColumn(TIMELINE, duration=t)], recording=self.rec,
                        columns=rr.TextLog.columns(text=[e[2] for e in events],
                                                   level=[{"WARNING": "WARN"}.get(e[1], e[1]) for e in events]))


class RerunLog:
    """Streams a running trial to Rerun (implements :class:`~boatland.trial.sink.TrialSink`).

    Parameters
    ----------
    target : str
        ``spawn | serve | connect[=URL] | save=PATH.rrd`` (:func:`parse_target`).
    recording_id : str, optional
        Shared with the MCAP log so a replay of it is the same recording.

    Blocks are buffered and sent every :data:`FLUSH_EVERY` seconds of simulated time (batched
    ``send_columns``); the viewer target is opened (and checked) in :meth:`start`.
    """

    def __init__(self, target: str, *, recording_id: str | None = None, quiet: bool = False,
                 bind: str = DEFAULT_BIND, port: int = DEFAULT_PORT):
        check_target(target, bind=bind, port=port)   # a bad spec, an absent viewer, a busy port: fail now
        self.target, self.recording_id, self.quiet, self.bind, self.port = target, recording_id, quiet, bind, port
        self.rec, self.kind, self.where, self.file, self._closed = None, None, None, None, False

    def start(self, info) -> None:
        self.info = info
        nc = np.asarray(info.contacts[0]).reshape(-1, 3).shape[0]
        scene = scene_from_trial(info.setup, info.contacts)
        self.rec, self.kind, self.where, self.file = open_stream(
            self.target, recording_id=self.recording_id, n_contacts=nc, quiet=self.quiet, bind=self.bind,
            port=self.port, scene=scene)
        self.view = RerunView(self.rec, scene, nc)
        self.view.static()
        self._tracker = LandingTracker(nc, settle_row(info))
        self._incidents = IncidentWatch(info.scenario.incidents, settle_row(info))
        self._eta = BowElevation(info)
        self._buf, self._events = [], []

    def steps(self, block) -> None:
        c = columns_from_block(block, self.info, self._tracker, self._eta(block.k0, block.k1))
        self._buf.append(Columns(**{k: np.array(v) for k, v in vars(c).items()}))
        self._events += step_events(block, c.slip, self._incidents)
        if self._buf[-1].t[-1] - self._buf[0].t[0] >= FLUSH_EVERY:
            self._send()

    def _send(self) -> None:
        if self._buf:
            self.view.columns(Columns.concatenate(self._buf))
        self.view.events(self._events)
        self._buf, self._events = [], []

    def finish(self, result) -> None:
        self._events.append(end_event(result))
        self._send()
        self.close()

    def close(self) -> None:
        """Flush; close a file target (writes its footer). A served stream stays up (:meth:`serve_until_interrupted`)."""
        if self.rec is None or self._closed:
            return
        self._closed = True
        try:
            self.rec.flush(timeout_sec=10.0) if self.kind == "connect" else self.rec.flush()
        except RuntimeError as exc:   # the viewer went away: the run itself is fine
            print(f"warning: rerun: {exc}", file=sys.stderr)
        if self.kind in ("save", "connect", "spawn"):
            self.rec.disconnect()
        if self.file is not None:
            self.file.close()


def serve_until_interrupted(where: str) -> None:
    """Keep a served stream up for viewers until Ctrl-C (only when stdin is a terminal; a non-interactive
    run returns at once so that nothing ever waits for a viewer)."""
    import time

    if not sys.stdin.isatty():
        print(f"rerun: not waiting for viewers (stdin is not a terminal); the server at {where} stops now",
              file=sys.stderr)
        return
    print(f"rerun: the run is finished; viewers can still open {where}. Ctrl-C to stop.", file=sys.stderr)
    try:
        while True:
            time.sleep(0.5)
    except KeyboardInterrupt:
        pass
