"""Java: what the tablet's command layer needs from a dialect, for lang_java: the reply a sent
message waits for, the constructor of a Send skeleton, the contract messages the runtime uses
(TT_ACTION_COMMAND, TT_COMMAND_ACK, TT_LOG, HEARTBEAT), answered set-points (SendSetpoint) and
the fields the command queue stamps (command_id, time_usec)."""

from __future__ import annotations

import re

from ..dialect.model import INTEGER_RANGES, Dialect, Field, Message
from .java_fields import enum_type, java_type

_ANSWERED_RE = re.compile(r"\b(?:answered|acknowledged|replied to) by ([A-Z][A-Z0-9_]*)", re.IGNORECASE)
_SAME_RE = re.compile(r"\bsame ([a-z][a-z0-9_]*)")


def expected_reply(m: Message, d: Dialect) -> tuple[Message, list[str]] | None:
    """The reply a sent message waits for, from its description ("Answered by X with the same
    f"): X and the fields that must match (scalar integer fields both messages have)."""
    hit = _ANSWERED_RE.search(m.description or "")
    if not hit:
        return None
    reply = d.messages_by_name.get(hit.group(1).upper())
    if reply is None or reply is m:
        return None
    fields = []
    for name_ in _SAME_RE.findall(m.description or ""):
        a, b = m.field(name_), reply.field(name_)
        if a and b and not a.array_length and not b.array_length and not a.is_float and not b.is_float \
                and a.type != "char" and b.type != "char" and name_ not in fields:
            fields.append(name_)
    return reply, fields


# Java types narrower than an enum's constants (int, or long past int): a field of such a type
# typed by an enum takes the constants' type in a Send skeleton, range-checked into the field.
_WIDTH = {"byte": 1, "short": 2, "int": 4, "long": 8}


def ctor_type(f: Field, d: Dialect) -> str:
    """The type of a Send skeleton's constructor parameter for field f: the field's Java type,
    or for a scalar typed by an enum whose constants are wider (a byte field, int constants)
    the constants' type, so that `new SendX(SomeEnum.ENTRY)` compiles without a cast."""
    e = d.enums_by_name.get(f.enum) if f.enum and not f.array_length else None
    own = java_type(f)
    if e is None or own not in _WIDTH:
        return own
    wider = enum_type(e)
    return wider if _WIDTH[wider] > _WIDTH[own] else own


def ctor_assign(m: Message, f: Field, d: Dialect) -> str:
    """The expression a Send skeleton's constructor assigns to field f: the argument, range
    checked and narrowed when ctor_type widened it; a copy of an array (a retry must pack the
    values given, whatever the caller does with its array afterwards)."""
    if f.array_length:
        return f"{f.name} == null ? null : {f.name}.clone()"
    own = java_type(f)
    if ctor_type(f, d) == own:
        return f.name
    lo, hi = (str(v) + ("L" if abs(v) >= 2**31 else "") for v in INTEGER_RANGES[f.type])
    return f'({own}) Wire.checkRange({f.name}, {lo}, {hi}, "{m.name}.{f.name}", "{f.type}")'


def ctor_doc(m: Message, d: Dialect) -> str:
    """The Javadoc of a Send skeleton's constructor."""
    text = "The values to send, packed anew on every try."
    narrowed = [f for f in m.fields if ctor_type(f, d) != java_type(f)]
    if narrowed:
        one = len(narrowed) == 1
        names = ", ".join(f"{f.name} ({f.declared_type})" for f in narrowed)
        text += (f" {names} take{'s' * one} the constants of {'its enum' if one else 'their enums'} as they are and "
                 f"{'is' if one else 'are'} range-checked into the field{'' if one else 's'}.")
    if any(f.array_length for f in m.fields):
        text += " Arrays are copied: changing yours afterwards changes nothing sent."
    return text


# Fields of a contract message the runtime itself reads or fills (dialects/ttapi.xml): the runtime
# uses the message only if the dialect has it with these fields (the generated runtime of a
# dialect without ttapi.xml, such as common.xml, still compiles).
CONTRACT_FIELDS = {
    "TT_ACTION_COMMAND": ("command_id", "time_usec"),
    "TT_COMMAND_ACK": ("command_id", "result"),
    "TT_LOG": ("id", "severity", "chunk_seq"),  # and its text, a char array (checked below)
    "HEARTBEAT": ("type", "autopilot"),  # the Session's own, a second (MAV_TYPE_GCS, MAV_AUTOPILOT_INVALID)
}


def has_contract(d: Dialect, name: str) -> bool:
    """Whether the dialect has the contract message `name` (complete, with the fields the
    runtime uses, as scalars)."""
    m = d.messages_by_name.get(name)
    if m is None or not m.complete:
        return False
    if name == "TT_LOG" and ((t := m.field("text")) is None or t.type != "char" or not t.array_length):
        return False
    return all((f := m.field(n)) is not None and not f.array_length and not f.is_float and f.type != "char"
               for n in CONTRACT_FIELDS[name])


def has_setpoints(d: Dialect) -> bool:
    """Whether the dialect has answered set-points (SendSetpoint): ttapi.xml's DJI_POSE_STAMPED
    with its SETPOINT topic, and TT_LOG for the refusals."""
    m = d.messages_by_name.get("DJI_POSE_STAMPED")
    if m is None or not m.complete or not has_contract(d, "TT_LOG"):
        return False
    shape = {"target_system": ("uint8_t", 0), "sec": ("uint32_t", 0), "nsec": ("uint32_t", 0),
             "topic_name": ("uint8_t", 0), "position": ("double", 3), "orientation": ("double", 4)}
    for name, (t, n) in shape.items():
        f = m.field(name)
        if f is None or f.type != t or (f.array_length or 0) != n:
            return False
    topics = next((e for e in d.enums if e.name == "DJI_TOPIC_NAME"), None)
    return topics is not None and any(x.name == "DJI_TOPIC_NAME_SETPOINT" for x in topics.entries)


def stamped_fields(m: Message) -> dict[str, str]:
    """The fields of a sent message the command queue fills when the app leaves them 0: a scalar
    `command_id` (uint16_t or uint32_t) gets the queue's id for the submission, and then a
    `time_usec` (uint64_t) the time it was submitted (so an (id, time) pair is never reused,
    even by an app that restarts and numbers its commands afresh). Name -> what fills it."""
    cid = m.field("command_id")
    if cid is None or cid.array_length or cid.type not in ("uint16_t", "uint32_t"):
        return {}
    out = {"command_id": "ctx.commandId()"}
    t = m.field("time_usec")
    if t is not None and not t.array_length and t.type == "uint64_t":
        out["time_usec"] = "ctx.issuedUsec()"
    return out


def scalar_target(m: Message) -> bool:
    f = m.field("target_system")
    return bool(f and not f.array_length and f.type == "uint8_t")



def reply_conditions(m: Message, d: Dialect) -> list[str]:
    """Java conditions on `reply` (the expected reply message) for a Send skeleton."""
    r = expected_reply(m, d)
    if r is None:
        return []
    reply, fields = r
    stamped = stamped_fields(m)
    conds = [f"reply.{f} == this.{f}" if f not in stamped else f"reply.{f} == (this.{f} != 0 ? this.{f} : {stamped[f]})"
             for f in fields]
    if scalar_target(reply):
        conds.append("(reply.target_system == 0 || reply.target_system == ctx.sysId())")
    return conds

