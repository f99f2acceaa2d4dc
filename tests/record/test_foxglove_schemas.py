"""Our Foxglove schemas against the published ones (the ``foxglove-schemas-protobuf`` package, a test
dependency): every field of every ``foxglove.*`` message a run log carries has the published name, number,
type, label and message/enum type, and every enum value its published number — so Foxglove decodes the
logs as its own messages (field numbers are all a decoder sees)."""

import importlib

import pytest
from google.protobuf import descriptor_pb2

from boatland.record.schemas import SCHEMA_NAMES, file_descriptor_set


def _ours():
    """name → DescriptorProto of every foxglove message in the logs' schemas (dependencies included)."""
    out = {}
    for schema in SCHEMA_NAMES:
        fds = descriptor_pb2.FileDescriptorSet.FromString(file_descriptor_set(schema))
        for f in fds.file:
            if f.package == "foxglove":
                for m in f.message_type:
                    out[m.name] = m
    return out


OURS = _ours()


def _published(name: str) -> descriptor_pb2.DescriptorProto:
    module = importlib.import_module(f"foxglove_schemas_protobuf.{name}_pb2")
    proto = descriptor_pb2.DescriptorProto()
    module.DESCRIPTOR.message_types_by_name[name].CopyToProto(proto)
    return proto


def test_the_logs_use_these_foxglove_messages():
    assert {"FrameTransform", "SceneUpdate", "SceneEntity", "Log", "ArrowPrimitive", "Pose", "Vector3",
            "Quaternion", "Color"} <= set(OURS)


@pytest.mark.parametrize("name", sorted(OURS))
def test_fields_match_the_published_schema(name):
    ours, pub = OURS[name], _published(name)
    published = {f.number: f for f in pub.field}
    for f in ours.field:
        p = published.get(f.number)
        assert p is not None, f"{name}.{f.name}: field number {f.number} is not in the published schema"
        assert (f.name, f.type, f.label, f.type_name) == (p.name, p.type, p.label, p.type_name), (name, f.name)
    for e in ours.enum_type:
        pe = {x.name: x for x in pub.enum_type}[e.name]
        assert {v.name: v.number for v in e.value} == {v.name: v.number for v in pe.value}, (name, e.name)
