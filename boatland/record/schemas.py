"""Protobuf schemas of the run log, built at runtime (no ``protoc``), and a vectorised encoder.

Channels of a boatland MCAP (all protobuf; ``log_time`` = simulated time in ns from the trial start):

==================  ==========================  ===========================================================
topic               schema                      content (one message per step unless said)
==================  ==========================  ===========================================================
``/tf``             ``foxglove.FrameTransform`` world → vessel pose (reference point, exact rotation)
``/events``         ``foxglove.Log``            contact events, incidents, end of run (rare)
``/vessel/state``   ``boatland.VesselState``    6-DOF motions ``x`` and velocities ``v`` (local frame)
``/vessel/loads``   ``boatland.VesselLoads``    thrust, wave excitation (6), wave elevation at the bow
``/fender/state``   ``boatland.FenderState``    per contact: mode, f_n, friction, needed, available, slip
==================  ==========================  ===========================================================

The Foxglove messages follow ``foxglove/schemas`` field for field (names and numbers), so Foxglove
and Rerun's MCAP importer recognise them by their schema name. Our own messages hold only fixed-size
fields (doubles, one-byte enums) and every field is always written (zeros and NaN included), so every
step's messages have the same bytes layout and a whole block is serialised at once
(:class:`boatland.record.mcap_log._Layout`), never one Python object per step. The FrameTransform
timestamp is written with fixed-width (5-byte) varints for the same reason: valid protobuf, which
parsers decode like the minimal form.
"""

from __future__ import annotations

from google.protobuf import descriptor_pb2, descriptor_pool, message_factory, timestamp_pb2

__all__ = ["TOPICS", "SCHEMA_NAMES", "file_descriptor_set", "message_class", "VESSEL_STATE_FIELDS",
           "VESSEL_LOADS_FIELDS", "CONTACT_FIELDS", "LOG_LEVEL"]

DOUBLE, INT64, INT32, UINT32, STRING, MESSAGE, ENUM, FIXED32 = 1, 3, 5, 13, 9, 11, 14, 7
OPTIONAL, REPEATED = 1, 3

VESSEL_STATE_FIELDS = ("t", "surge", "sway", "heave", "roll", "pitch", "yaw",
                       "u", "v", "w", "p", "q", "r")
VESSEL_LOADS_FIELDS = ("t", "thrust", "F_surge", "F_sway", "F_heave", "M_roll", "M_pitch", "M_yaw",
                       "wave_elevation_bow")
# per contact; "mode" (enum, 0 open, 1 stick, 2 slip) is field 1, the doubles follow
CONTACT_FIELDS = ("normal_force", "friction_vertical", "friction_horizontal", "needed", "available",
                  "slip_distance", "plane_vertical", "plane_horizontal")
LOG_LEVEL = {"UNKNOWN": 0, "DEBUG": 1, "INFO": 2, "WARNING": 3, "ERROR": 4, "FATAL": 5}

TOPICS = {"/tf": "foxglove.FrameTransform", "/events": "foxglove.Log", "/vessel/state": "boatland.VesselState",
          "/vessel/loads": "boatland.VesselLoads", "/fender/state": "boatland.FenderState"}
SCHEMA_NAMES = frozenset(TOPICS.values())


def _msg(fdp, name, fields):
    m = fdp.message_type.add(name=name)
    for number, (fname, ftype, *rest) in enumerate(fields, 1):
        f = m.field.add(name=fname, number=number, type=ftype, label=REPEATED if "repeated" in rest else OPTIONAL)
        if ftype in (MESSAGE, ENUM):
            f.type_name = rest[0]
    return m


def _files() -> list[descriptor_pb2.FileDescriptorProto]:
    ts = descriptor_pb2.FileDescriptorProto()
    timestamp_pb2.DESCRIPTOR.CopyToProto(ts)
    vec = descriptor_pb2.FileDescriptorProto(name="foxglove/Vector3.proto", package="foxglove", syntax="proto3")
    _msg(vec, "Vector3", [("x", DOUBLE), ("y", DOUBLE), ("z", DOUBLE)])
    quat = descriptor_pb2.FileDescriptorProto(name="foxglove/Quaternion.proto", package="foxglove", syntax="proto3")
    _msg(quat, "Quaternion", [("x", DOUBLE), ("y", DOUBLE), ("z", DOUBLE), ("w", DOUBLE)])
    tf = descriptor_pb2.FileDescriptorProto(
        name="foxglove/FrameTransform.proto", package="foxglove", syntax="proto3",
        dependency=["google/protobuf/timestamp.proto", "foxglove/Quaternion.proto", "foxglove/Vector3.proto"])
    _msg(tf, "FrameTransform", [("timestamp", MESSAGE, ".google.protobuf.Timestamp"), ("parent_frame_id", STRING),
                                ("child_frame_id", STRING), ("translation", MESSAGE, ".foxglove.Vector3"),
                                ("rotation", MESSAGE, ".foxglove.Quaternion")])
    log = descriptor_pb2.FileDescriptorProto(name="foxglove/Log.proto", package="foxglove", syntax="proto3",
                                             dependency=["google/protobuf/timestamp.proto"])
    m = _msg(log, "Log", [("timestamp", MESSAGE, ".google.protobuf.Timestamp"), ("level", ENUM, ".foxglove.Log.Level"),
                          ("message", STRING), ("name", STRING), ("file", STRING), ("line", FIXED32)])
    lvl = m.enum_type.add(name="Level")
    for k, v in LOG_LEVEL.items():
        lvl.value.add(name=k, number=v)
    own = descriptor_pb2.FileDescriptorProto(name="boatland/record.proto", package="boatland", syntax="proto3")
    _msg(own, "VesselState", [(f, DOUBLE) for f in VESSEL_STATE_FIELDS])
    _msg(own, "VesselLoads", [(f, DOUBLE) for f in VESSEL_LOADS_FIELDS])
    c = _msg(own, "Contact", [("mode", ENUM, ".boatland.Contact.Mode")] + [(f, DOUBLE) for f in CONTACT_FIELDS])
    mode = c.enum_type.add(name="Mode")
    for k, v in (("OPEN", 0), ("STICK", 1), ("SLIP", 2)):
        mode.value.add(name=k, number=v)
    _msg(own, "FenderState", [("t", DOUBLE), ("contacts", MESSAGE, ".boatland.Contact", "repeated")])
    return [ts, vec, quat, tf, log, own]


_FILES = _files()
_POOL = descriptor_pool.DescriptorPool()
for _f in _FILES:
    _POOL.Add(_f)
_FILE_OF = {"foxglove.FrameTransform": {0, 1, 2, 3}, "foxglove.Log": {0, 4},
            "boatland.VesselState": {5}, "boatland.VesselLoads": {5}, "boatland.FenderState": {5}}


def file_descriptor_set(schema_name: str) -> bytes:
    """The serialised ``FileDescriptorSet`` of ``schema_name`` with its dependencies (MCAP schema data)."""
    fds = descriptor_pb2.FileDescriptorSet()
    for i in sorted(_FILE_OF[schema_name]):
        fds.file.append(_FILES[i])
    return fds.SerializeToString()


def message_class(schema_name: str):
    """Python protobuf class of one of our schemas (for rare messages and for tests)."""
    return message_factory.GetMessageClass(_POOL.FindMessageTypeByName(schema_name))
