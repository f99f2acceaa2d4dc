"""Protobuf schemas of the run log, built at runtime (no ``protoc``), and a vectorised encoder.

Channels of a boatland MCAP (all protobuf). Times: ``log_time`` = :data:`start_time_ns` (the run's
wall-clock start, whole seconds since the Unix epoch, UTC; metadata ``boatland.run``) + simulated time
[ns]; the own messages also carry the simulated time ``t`` [s]. Angles are in degrees (field names
ending in ``_deg``, rates in ``_deg_s``), everything else SI. Format version :data:`LOG_FORMAT` (2);
version-1 logs (no ``log_format`` in the metadata: radians, ``log_time`` = simulated time) are still
read (:mod:`boatland.record.reader`).

==================  ==========================  ===========================================================
topic               schema                      content (one message per step unless said)
==================  ==========================  ===========================================================
``/tf``             ``foxglove.FrameTransform`` world → vessel pose (reference point, exact rotation)
``/scene``          ``foxglove.SceneUpdate``    static 3-D scene, once at t = 0: hull (wetted part and
                                                topsides/deck when the database has them), monopile,
                                                landing tubes, fender lines, sea level
                                                (:mod:`boatland.record.foxglove_scene`)
``/fender/forces``  ``foxglove.SceneUpdate``    fender force arrows on the vessel (normal and friction of
                                                each contact, coloured open / stick / slip / off)
``/events``         ``foxglove.Log``            contact events, incidents, end of run (rare)
``/vessel/state``   ``boatland.VesselState``    6-DOF motions and velocities (local frame; deg, deg/s)
``/vessel/loads``   ``boatland.VesselLoads``    thrust, wave excitation (6), wave elevation at the bow
``/fender/state``   ``boatland.FenderState``    per contact: mode, f_n, friction, needed, available, slip
==================  ==========================  ===========================================================

The Foxglove messages follow ``foxglove/schemas`` field for field (names and numbers), so Foxglove
and Rerun's MCAP importer recognise them by their schema name. Our own messages hold only fixed-size
fields (doubles, one-byte enums) and every field is always written (zeros and NaN included), so every
step's messages have the same bytes layout and a whole block is serialised at once
(:class:`boatland.record.mcap_log._Layout`), never one Python object per step. Timestamps are written
with fixed-width (5-byte) varints for the same reason: valid protobuf, which parsers decode like the
minimal form.
"""

from __future__ import annotations

import math

from google.protobuf import descriptor_pb2, descriptor_pool, duration_pb2, message_factory, timestamp_pb2

__all__ = ["TOPICS", "STEP_TOPICS", "SCHEMA_NAMES", "LOG_FORMAT", "RAD2DEG", "file_descriptor_set", "message_class",
           "VESSEL_STATE_FIELDS", "VESSEL_LOADS_FIELDS", "CONTACT_FIELDS", "LOG_LEVEL", "ANGLE_FIELDS",
           "V1_VESSEL_STATE_FIELDS"]

DOUBLE, INT64, INT32, UINT32, STRING, MESSAGE, ENUM, FIXED32, BOOL, BYTES = 1, 3, 5, 13, 9, 11, 14, 7, 8, 12
OPTIONAL, REPEATED = 1, 3

#: Version of the log's content: 2 = angles in degrees, ``log_time`` from the run's wall-clock start;
#: 1 (no ``log_format`` in the metadata) = radians, ``log_time`` = simulated time.
LOG_FORMAT = 2
#: Degrees per radian (the factor of ``np.degrees``); the reader divides by it (≤ 1 ulp from the radians).
RAD2DEG = 180.0 / math.pi

VESSEL_STATE_FIELDS = ("t", "surge", "sway", "heave", "roll_deg", "pitch_deg", "yaw_deg",
                       "u", "v", "w", "p_deg_s", "q_deg_s", "r_deg_s")
#: The same fields (same numbers) in format 1, in radians and rad/s.
V1_VESSEL_STATE_FIELDS = ("t", "surge", "sway", "heave", "roll", "pitch", "yaw", "u", "v", "w", "p", "q", "r")
#: Columns of :data:`VESSEL_STATE_FIELDS` in degrees (from format 2 on).
ANGLE_FIELDS = (4, 5, 6, 10, 11, 12)
VESSEL_LOADS_FIELDS = ("t", "thrust", "F_surge", "F_sway", "F_heave", "M_roll", "M_pitch", "M_yaw",
                       "wave_elevation_bow")
# per contact; "mode" (enum, 0 open, 1 stick, 2 slip, 3 off the landing) is field 1, the doubles follow
CONTACT_FIELDS = ("normal_force", "friction_vertical", "friction_horizontal", "needed", "available",
                  "slip_distance", "plane_vertical", "plane_horizontal")
LOG_LEVEL = {"UNKNOWN": 0, "DEBUG": 1, "INFO": 2, "WARNING": 3, "ERROR": 4, "FATAL": 5}

TOPICS = {"/tf": "foxglove.FrameTransform", "/scene": "foxglove.SceneUpdate", "/events": "foxglove.Log",
          "/vessel/state": "boatland.VesselState", "/vessel/loads": "boatland.VesselLoads",
          "/fender/state": "boatland.FenderState", "/fender/forces": "foxglove.SceneUpdate"}
#: The topics with one message per step, in the order of a step's payload row.
STEP_TOPICS = ("/tf", "/vessel/state", "/vessel/loads", "/fender/state", "/fender/forces")
SCHEMA_NAMES = frozenset(TOPICS.values())


def _msg(fdp, name, fields):
    m = fdp.message_type.add(name=name)
    for number, (fname, ftype, *rest) in enumerate(fields, 1):
        f = m.field.add(name=fname, number=number, type=ftype, label=REPEATED if "repeated" in rest else OPTIONAL)
        if ftype in (MESSAGE, ENUM):
            f.type_name = rest[0]
    return m


def _enum(m, name, values):
    e = m.enum_type.add(name=name)
    for k, v in values:
        e.value.add(name=k, number=v)


def _fox(name, deps, *messages):
    """``foxglove/<name>.proto`` with ``messages`` = (message name, fields) pairs."""
    f = descriptor_pb2.FileDescriptorProto(name=f"foxglove/{name}.proto", package="foxglove", syntax="proto3",
                                           dependency=list(deps))
    return f, [_msg(f, n, fields) for n, fields in messages]


def _files() -> dict[str, descriptor_pb2.FileDescriptorProto]:
    """Every file, by name: Foxglove's schemas as in ``foxglove/schemas`` (names and field numbers), ours."""
    ts, du = descriptor_pb2.FileDescriptorProto(), descriptor_pb2.FileDescriptorProto()
    timestamp_pb2.DESCRIPTOR.CopyToProto(ts)
    duration_pb2.DESCRIPTOR.CopyToProto(du)
    TS, DU = "google/protobuf/timestamp.proto", "google/protobuf/duration.proto"
    V, Q, C, P3, PO = "foxglove/Vector3.proto", "foxglove/Quaternion.proto", "foxglove/Color.proto", \
        "foxglove/Point3.proto", "foxglove/Pose.proto"
    vec3, quat, pt3 = ([(k, DOUBLE) for k in keys] for keys in ("xyz", "xyzw", "xyz"))
    files = [ts, du]
    files.append(_fox("Vector3", [], ("Vector3", vec3))[0])
    files.append(_fox("Quaternion", [], ("Quaternion", quat))[0])
    files.append(_fox("Point3", [], ("Point3", pt3))[0])
    files.append(_fox("Color", [], ("Color", [(k, DOUBLE) for k in "rgba"]))[0])
    files.append(_fox("Pose", [V, Q], ("Pose", [("position", MESSAGE, ".foxglove.Vector3"),
                                                ("orientation", MESSAGE, ".foxglove.Quaternion")]))[0])
    files.append(_fox("KeyValuePair", [], ("KeyValuePair", [("key", STRING), ("value", STRING)]))[0])
    pose, color = ("pose", MESSAGE, ".foxglove.Pose"), ("color", MESSAGE, ".foxglove.Color")
    size = ("size", MESSAGE, ".foxglove.Vector3")
    files.append(_fox("FrameTransform", [TS, Q, V], ("FrameTransform", [
        ("timestamp", MESSAGE, ".google.protobuf.Timestamp"), ("parent_frame_id", STRING), ("child_frame_id", STRING),
        ("translation", MESSAGE, ".foxglove.Vector3"), ("rotation", MESSAGE, ".foxglove.Quaternion")]))[0])
    log, (m,) = _fox("Log", [TS], ("Log", [
        ("timestamp", MESSAGE, ".google.protobuf.Timestamp"), ("level", ENUM, ".foxglove.Log.Level"),
        ("message", STRING), ("name", STRING), ("file", STRING), ("line", FIXED32)]))
    _enum(m, "Level", LOG_LEVEL.items())
    files.append(log)
    files.append(_fox("ArrowPrimitive", [C, PO], ("ArrowPrimitive", [
        pose, ("shaft_length", DOUBLE), ("shaft_diameter", DOUBLE), ("head_length", DOUBLE),
        ("head_diameter", DOUBLE), color]))[0])
    files.append(_fox("CubePrimitive", [C, PO, V], ("CubePrimitive", [pose, size, color]))[0])
    files.append(_fox("SpherePrimitive", [C, PO, V], ("SpherePrimitive", [pose, size, color]))[0])
    files.append(_fox("CylinderPrimitive", [C, PO, V], ("CylinderPrimitive", [
        pose, size, ("bottom_scale", DOUBLE), ("top_scale", DOUBLE), color]))[0])
    line, (m,) = _fox("LinePrimitive", [C, P3, PO], ("LinePrimitive", [
        ("type", ENUM, ".foxglove.LinePrimitive.Type"), pose, ("thickness", DOUBLE), ("scale_invariant", BOOL),
        ("points", MESSAGE, ".foxglove.Point3", "repeated"), color,
        ("colors", MESSAGE, ".foxglove.Color", "repeated"), ("indices", FIXED32, "repeated")]))
    _enum(m, "Type", [("LINE_STRIP", 0), ("LINE_LOOP", 1), ("LINE_LIST", 2)])
    files.append(line)
    files.append(_fox("TriangleListPrimitive", [C, P3, PO], ("TriangleListPrimitive", [
        pose, ("points", MESSAGE, ".foxglove.Point3", "repeated"), color,
        ("colors", MESSAGE, ".foxglove.Color", "repeated"), ("indices", FIXED32, "repeated")]))[0])
    files.append(_fox("TextPrimitive", [C, PO], ("TextPrimitive", [
        pose, ("billboard", BOOL), ("font_size", DOUBLE), ("scale_invariant", BOOL), color, ("text", STRING)]))[0])
    files.append(_fox("ModelPrimitive", [C, PO, V], ("ModelPrimitive", [
        pose, ("scale", MESSAGE, ".foxglove.Vector3"), color, ("override_color", BOOL), ("url", STRING),
        ("media_type", STRING), ("data", BYTES)]))[0])
    prims = ["ArrowPrimitive", "CubePrimitive", "CylinderPrimitive", "KeyValuePair", "LinePrimitive",
             "ModelPrimitive", "SpherePrimitive", "TextPrimitive", "TriangleListPrimitive"]
    files.append(_fox("SceneEntity", [f"foxglove/{p}.proto" for p in prims] + [DU, TS], ("SceneEntity", [
        ("timestamp", MESSAGE, ".google.protobuf.Timestamp"), ("frame_id", STRING), ("id", STRING),
        ("lifetime", MESSAGE, ".google.protobuf.Duration"), ("frame_locked", BOOL),
        ("metadata", MESSAGE, ".foxglove.KeyValuePair", "repeated"),
        ("arrows", MESSAGE, ".foxglove.ArrowPrimitive", "repeated"),
        ("cubes", MESSAGE, ".foxglove.CubePrimitive", "repeated"),
        ("spheres", MESSAGE, ".foxglove.SpherePrimitive", "repeated"),
        ("cylinders", MESSAGE, ".foxglove.CylinderPrimitive", "repeated"),
        ("lines", MESSAGE, ".foxglove.LinePrimitive", "repeated"),
        ("triangles", MESSAGE, ".foxglove.TriangleListPrimitive", "repeated"),
        ("texts", MESSAGE, ".foxglove.TextPrimitive", "repeated"),
        ("models", MESSAGE, ".foxglove.ModelPrimitive", "repeated")]))[0])
    dele, (m,) = _fox("SceneEntityDeletion", [TS], ("SceneEntityDeletion", [
        ("timestamp", MESSAGE, ".google.protobuf.Timestamp"), ("type", ENUM, ".foxglove.SceneEntityDeletion.Type"),
        ("id", STRING)]))
    _enum(m, "Type", [("MATCHING_ID", 0), ("ALL", 1)])
    files.append(dele)
    files.append(_fox("SceneUpdate", ["foxglove/SceneEntity.proto", "foxglove/SceneEntityDeletion.proto"], (
        "SceneUpdate", [("deletions", MESSAGE, ".foxglove.SceneEntityDeletion", "repeated"),
                        ("entities", MESSAGE, ".foxglove.SceneEntity", "repeated")]))[0])
    own = descriptor_pb2.FileDescriptorProto(name="boatland/record.proto", package="boatland", syntax="proto3")
    _msg(own, "VesselState", [(f, DOUBLE) for f in VESSEL_STATE_FIELDS])
    _msg(own, "VesselLoads", [(f, DOUBLE) for f in VESSEL_LOADS_FIELDS])
    c = _msg(own, "Contact", [("mode", ENUM, ".boatland.Contact.Mode")] + [(f, DOUBLE) for f in CONTACT_FIELDS])
    _enum(c, "Mode", [("OPEN", 0), ("STICK", 1), ("SLIP", 2), ("OFF", 3)])
    _msg(own, "FenderState", [("t", DOUBLE), ("contacts", MESSAGE, ".boatland.Contact", "repeated")])
    files.append(own)
    return {f.name: f for f in files}


_FILES = _files()
_POOL = descriptor_pool.DescriptorPool()
for _f in _FILES.values():
    _POOL.Add(_f)
_FILE_OF_TYPE = {t.full_name: name for name in _FILES
                 for t in _POOL.FindFileByName(name).message_types_by_name.values()}


def _closure(name: str, out: list) -> list:
    """``name`` and the files it depends on, dependencies first."""
    for dep in _FILES[name].dependency:
        _closure(dep, out)
    if name not in out:
        out.append(name)
    return out


def file_descriptor_set(schema_name: str) -> bytes:
    """The serialised ``FileDescriptorSet`` of ``schema_name`` with its dependencies (MCAP schema data)."""
    fds = descriptor_pb2.FileDescriptorSet()
    for name in _closure(_FILE_OF_TYPE[schema_name], []):
        fds.file.append(_FILES[name])
    return fds.SerializeToString()


def message_class(schema_name: str):
    """Python protobuf class of one of our schemas (for rare messages and for tests)."""
    return message_factory.GetMessageClass(_POOL.FindMessageTypeByName(schema_name))
