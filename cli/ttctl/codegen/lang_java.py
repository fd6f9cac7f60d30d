"""Java: bindings for Android (API 24+, Java 8 syntax, builds with --release 8 and 11), a
conformance program, and tablet command skeletons (command pattern, one command queue).

Layout under the output root, for a dialect whose identifier is `ttapi`:

  java/ttctl/ttapi/Ttapi.java        registry: msgid -> MessageInfo, payload -> message object
  java/ttctl/ttapi/runtime/          framing, CRC, stream parser, dispatcher, links, commands
  java/ttctl/ttapi/msg/              one class per message
  java/ttctl/ttapi/enums/            one class of int/long constants per enum
  java/ttctl/ttapi/commands/         skeletons: Send<Msg> per message the tablet sends,
                                     Receive<Msg> per message it receives (yours to edit)
  java/Conformance.java              the `D <hex>` / `E <json>` conformance program
  java/ConformanceJson.java          its JSON: answers written, requests read, values to fields

Field types and expressions: java_fields; the tablet's command contract: java_tablet.
"""

from __future__ import annotations

import re
from typing import Any

from ..dialect.model import Dialect, Message
from ..dialect.names import JAVA_KEYWORDS, JAVA_RESERVED_TYPES, camel
from .engine import Output, dialect_ident, receives, sends
from .java_fields import (
    TYPE_MAPPING,
    class_name,
    default_value,
    enum_class,
    enum_table,
    enum_type,
    field_doc,
    is_bytes,
    is_text,
    java_long,
    java_string,
    java_type,
    javadoc,
    json_in,
    json_out,
    pack_lines,
    to_string_expr,
    unpack_lines,
)
from .java_tablet import (
    ctor_assign,
    ctor_doc,
    ctor_type,
    expected_reply,
    has_contract,
    has_setpoints,
    reply_conditions,
    scalar_target,
    stamped_fields,
)

name = "java"

# The runtime package, one class per file. Generated code in other packages refers to these by
# simple name (imported) unless a message or skeleton class has the same simple name.
RUNTIME_FILES = [
    "Crc", "Wire", "Unsigned", "MavlinkMessage", "MessageInfo", "MavlinkDialect",
    "DecodeException", "Frame", "Parser", "Dispatcher", "Link", "UdpLink", "CommandContext",
    "CommandException", "Command", "MessageMatcher", "SendCommand", "ReceiveCommand", "CommandJob", "CommandIds",
    "CommandEnds", "CommandQueue",
    "LinkScheduler", "PacketBuilder", "DjiReceiving", "DjiLink", "PayloadLink", "PipelineLink",
    "Packetizer", "PacketReceiver", "Signing", "UdpForward", "Callbacks", "Session",
    # the ground-station bridge (issue 22)
    "GcsRules", "GcsUplink", "GcsQuality", "GcsRoutes", "GcsV1", "GcsV1Stations", "GcsProblems",
    "GcsResend", "GcsMissions", "GcsDownloads", "GcsParamLists", "GcsProtocols", "GcsBridgeCore", "GcsBridge",
]
RUNTIME_CLASSES = frozenset(RUNTIME_FILES + ["SendSetpoint"])
# File transfer (package <root>.transfer), for dialects that have ttctl's file messages.
TRANSFER_FILES = ["RangeSet", "Names", "TransferConfig", "TransferResult", "Transfer", "LossEstimate", "FileSender",
                  "Deflate", "ReceiveDir", "Incoming", "Partial", "FileReceiver", "FileFetch", "ServedFolder",
                  "TransferRouter", "TransferTimer", "FileTransfers"]
TRANSFER_FILES += ["SentLog", "ReceiverStatuses", "Sharing"]  # split out of FileSender and FileReceiver; rate grants
TRANSFER_FILES += ["Geometry"]  # the data frames the link's packet size allows
TRANSFER_FILES += ["DataPath"]  # file data on a MOP pipeline while it is open (issue 27)
TRANSFER_FILES += ["Reports"]  # a receiver's report as the sender reads it: ranges, or a map (TT_FILE_MAP)
TRANSFER_MESSAGES = {"TT_FILE_OFFER", "TT_FILE_STATUS", "TT_FILE_REASON", "TT_FILE_DATA", "TT_FILE_DATA_WIDE",
                     "TT_FILE_DATA_FIT", "TT_FILE_REQUEST", "TT_FILE_MAP"}



def package(d: Dialect, override: str | None = None) -> str:
    """The Java root package of a dialect: `override` (--java-package), else ttctl.<ident>
    (ident_ if it is a Java keyword)."""
    if override:
        return override
    ident = dialect_ident(d)
    return f"ttctl.{ident}_" if ident in JAVA_KEYWORDS else f"ttctl.{ident}"


def registry_class(d: Dialect) -> str:
    """The registry class: the dialect's name in CamelCase, + "Dialect" if that would shadow a
    java.lang or runtime class."""
    n = camel(dialect_ident(d))
    taken = n in JAVA_RESERVED_TYPES or n in RUNTIME_CLASSES or n in ("Conformance", "ConformanceJson")
    return f"{n}Dialect" if taken else n


def free_name(name: str, taken: list[str]) -> str:
    """`name`, or with `_` appended until none of `taken` is called that (a private member of a
    generated class that an entry or a field would otherwise redefine)."""
    while name in taken:
        name += "_"
    return name


def tablet_commands(d: Dialect) -> list[Message]:
    """The messages that get a Send skeleton: those of the root dialect the tablet sends, and
    TT_ACTION_COMMAND from an included ttapi.xml (the README's take-off, `SendTtActionCommand`,
    is an app's first command whatever its dialect)."""
    out = sends(d, "tablet")
    cmd = d.messages_by_name.get("TT_ACTION_COMMAND")
    if cmd is not None and cmd not in out and has_contract(d, "TT_ACTION_COMMAND") \
            and has_contract(d, "TT_COMMAND_ACK"):
        out = sorted([*out, cmd], key=lambda m: m.id)
    return out


class _Refs:
    """How generated code outside the runtime package names runtime and message classes:
    imported simple names unless two classes would share one."""

    def __init__(self, d: Dialect, root: str) -> None:
        self.root = root
        self.msg_names = {class_name(m, d) for m in d.messages if m.complete}
        self.d = d
        # a message class or a field (Wire, Unsigned) of a runtime class's name hides it in Java
        fields = {f.name for m in d.messages for f in m.fields}
        self.clash = {n for n in RUNTIME_CLASSES if n in self.msg_names or n in fields}

    def rt(self, simple: str, own_class: str = "") -> str:
        if simple in self.clash or simple == own_class:
            return f"{self.root}.runtime.{simple}"
        return simple

    def qualify(self, code: str) -> str:
        """Code naming runtime classes by simple name, with the clashing ones qualified."""
        for n in self.clash:
            code = re.sub(rf"\b{n}\.", f"{self.root}.runtime.{n}.", code)
        return code

    def rt_imports(self, names: list[str], own_class: str = "") -> list[str]:
        return [f"import {self.root}.runtime.{n};" for n in sorted(set(names))
                if n not in self.clash and n != own_class]

    def msg(self, m: Message, own_class: str = "") -> str:
        cn = class_name(m, self.d)
        if cn in RUNTIME_CLASSES or cn == own_class:
            return f"{self.root}.msg.{cn}"
        return cn

    def msg_imports(self, msgs: list[Message], own_class: str = "") -> list[str]:
        out = set()
        for m in msgs:
            cn = class_name(m, self.d)
            if cn not in RUNTIME_CLASSES and cn != own_class:
                out.add(f"import {self.root}.msg.{cn};")
        return sorted(out)


class _Java:
    name = "java"

    def __init__(self, override: str | None = None) -> None:
        self.override = override  # --java-package; None: ttctl.<ident>

    def outputs(self, d: Dialect) -> list[Output]:
        root = "java/" + package(d, self.override).replace(".", "/")
        outs = [Output(f"{root}/{registry_class(d)}.java", "java/Registry.java.j2")]
        for n in RUNTIME_FILES:
            outs.append(Output(f"{root}/runtime/{n}.java", f"java/runtime/{n}.java.j2"))
        if has_setpoints(d):
            outs.append(Output(f"{root}/runtime/SendSetpoint.java", "java/runtime/SendSetpoint.java.j2"))
        if TRANSFER_MESSAGES.issubset(m.name for m in d.messages if m.complete):
            for n in TRANSFER_FILES:
                outs.append(Output(f"{root}/transfer/{n}.java", f"java/runtime/transfer/{n}.java.j2"))
        for m in sorted((m for m in d.messages if m.complete), key=lambda m: m.id):
            outs.append(Output(f"{root}/msg/{class_name(m, d)}.java", "java/Message.java.j2", context={"m": m}))
        for e in sorted(d.enums, key=lambda e: e.name):
            outs.append(Output(f"{root}/enums/{enum_class(e.name, d)}.java", "java/Enum.java.j2", context={"e": e}))
        outs.append(Output("java/Conformance.java", "java/Conformance.java.j2"))
        outs.append(Output("java/ConformanceJson.java", "java/ConformanceJson.java.j2"))
        for m in tablet_commands(d):
            outs.append(Output(f"{root}/commands/Send{class_name(m, d)}.java", "java/SendSkeleton.java.j2",
                               skeleton=True, context={"m": m, "cls": f"Send{class_name(m, d)}"}))
        for m in receives(d, "tablet"):
            outs.append(Output(f"{root}/commands/Receive{class_name(m, d)}.java", "java/ReceiveSkeleton.java.j2",
                               skeleton=True, context={"m": m, "cls": f"Receive{class_name(m, d)}"}))
        return outs

    def owned_dirs(self, d: Dialect) -> list[str]:
        root = "java/" + package(d, self.override).replace(".", "/")
        return [f"{root}/runtime", f"{root}/transfer", f"{root}/msg", f"{root}/enums"]

    def globals(self, d: Dialect) -> dict[str, Any]:
        pkg = package(d, self.override)
        refs = _Refs(d, pkg)
        return {
            "pkg": pkg,
            "registry": registry_class(d),
            "class_name": lambda m: class_name(m, d),
            "java_enum_class": lambda e: enum_class(e.name, d),
            "free_name": free_name,
            "java_type": java_type,
            "is_text": is_text,
            "is_bytes": is_bytes,
            "default_value": lambda f: default_value(f, d),
            "pack_lines": lambda m, f: [refs.qualify(x) for x in pack_lines(m, f)],
            "unpack_lines": lambda m, f: [refs.qualify(x) for x in unpack_lines(m, f)],
            "to_string_expr": lambda f: refs.qualify(to_string_expr(f)),
            "javadoc": javadoc,
            "field_doc": lambda f: field_doc(f, d, pkg),
            "java_string": java_string,
            "enum_type": enum_type,
            "enum_table": enum_table,
            "java_long": java_long,
            "java_longs": lambda vs: ", ".join(java_long(v) for v in vs),
            "json_out": json_out,
            "json_in": json_in,
            "expected_reply": lambda m: expected_reply(m, d),
            "reply_conditions": lambda m: reply_conditions(m, d),
            "scalar_target": scalar_target,
            "stamped_fields": stamped_fields,
            "has_contract": lambda name: has_contract(d, name),
            "has_transfers": TRANSFER_MESSAGES.issubset(m.name for m in d.messages if m.complete),
            "ctor_type": lambda f: ctor_type(f, d),
            "narrowed": lambda m: [f.name for f in m.fields if ctor_type(f, d) != java_type(f)],
            "ctor_doc": lambda m: ctor_doc(m, d),
            "ctor_assign": lambda m, f: refs.qualify(ctor_assign(m, f, d)),
            "type_mapping": TYPE_MAPPING,
            "rt": refs.rt,
            "rt_imports": refs.rt_imports,
            "msg_ref": refs.msg,
            "msg_imports": refs.msg_imports,
        }


LANG = _Java()
