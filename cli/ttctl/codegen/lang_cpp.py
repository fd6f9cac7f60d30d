"""C++: header-only C++17 bindings per dialect (runtime, enums, messages, an umbrella header),
a conformance program, and an onboard handler-plugin skeleton.

Layout under the output root (<ident>: the dialect's identifier; with --cpp-namespace a::b the
headers go to cpp/a/b/ instead of cpp/<ident>/):
  cpp/<ident>/runtime.hpp     the runtime; it includes its pieces (RUNTIME_HEADERS): the frame's
                              format, CRC, little-endian helpers, the message table, encoding,
                              decoding, Parser, dispatch (Outbox, Dispatcher, Plugin)
  cpp/<ident>/sha256.hpp      SHA-256 (signing and the file transfer's checks)
  cpp/<ident>/signing.hpp     MAVLink 2 signing (included by runtime.hpp)
  cpp/<ident>/packets.hpp     Packetizer and the packet-aware PacketReceiver (included by runtime.hpp)
  cpp/<ident>/scheduler.hpp   link::Scheduler: paced priorities, frames signed as they are placed
For a dialect that carries ttctl's runtime messages (it includes ttapi.xml), the onboard end of
the link, in namespace <ns>::link:
  cpp/<ident>/commands.hpp    the command server: each command executed once, acks recorded
  cpp/<ident>/transfer.hpp    file transfer (POSIX): the jail folder, resume, serving fetches; it
                              includes its pieces (TRANSFER_HEADERS): the protocol's numbers and
                              words, the name rules, byte ranges, storage, the receiver, the sender
  cpp/<ident>/node.hpp        link::Node: all of it on one link, heartbeat, timers; DttLink (DJI OSDK 4);
                              it includes its pieces (NODE_HEADERS): the config, the set-points'
                              answers (SetpointDesk), NodeContext, receiving, files, NodePump, DttLink
  cpp/<ident>/psdk_link.hpp   link::PsdkLink: a Node on DJI's Payload SDK low-speed channel (needs its header)
  cpp/<ident>/osdk_link.hpp   link::OsdkLink: a Node on DJI's Onboard SDK 3.x or 4.x DTT (needs its header)
  cpp/<ident>/pipe_link.hpp   link::PipeLink: a MOP pipeline beside a Node's link, over any SDK's PipeTransport
  cpp/<ident>/mop_link.hpp    link::MopLink: the pipeline on the Payload SDK's dji_mop_channel.h (needs its header)
  cpp/<ident>/osdk_mop_link.hpp  link::OsdkMopLink: the pipeline on the Onboard SDK 4.1's MopServer (M300)
  cpp/<ident>/udp_link.hpp    link::UdpLink: a Node on UDP (POSIX)
  cpp/<ident>/enums.hpp       one `enum class` per enum
  cpp/<ident>/messages.hpp    one struct per message
  cpp/<ident>/<ident>.hpp     umbrella header
  cpp/conformance.cpp         the D/E line-protocol program of the conformance tests
  cpp/conformance_json.hpp    its JSON: answers written, values to fields
  cpp/conformance_json_reader.hpp  its JSON reader: requests read, numbers kept as tokens
  cpp/onboard/<ident>_plugin.hpp   skeleton: handler stubs for what the onboard end receives
"""

from __future__ import annotations

from typing import Any

from ..dialect.model import Dialect, Enum, Field, Message
from ..dialect.names import C_RESERVED, CPP_KEYWORDS, RUNTIME_TYPE_NAMES, camel
from ..dialect.symbols import type_names
from .engine import Output, dialect_ident, receives
from .text import wrap

name = "cpp"

_CPP_TYPES = {
    "float": "float",
    "double": "double",
    "char": "char",
    "int8_t": "std::int8_t",
    "uint8_t": "std::uint8_t",
    "int16_t": "std::int16_t",
    "uint16_t": "std::uint16_t",
    "int32_t": "std::int32_t",
    "uint32_t": "std::uint32_t",
    "int64_t": "std::int64_t",
    "uint64_t": "std::uint64_t",
}

# Types and namespaces the runtime defines beside the messages and enums of a dialect.
RUNTIME_TYPES = RUNTIME_TYPE_NAMES  # the validator refuses those; checked here again for user templates
# The runtime: runtime.hpp includes the others, signing.hpp and packets.hpp, each in its place.
RUNTIME_HEADERS = ("runtime", "frame_format", "crc", "byte_order", "message_info", "encode", "decode", "parser",
                   "dispatch")
# File transfer: transfer.hpp includes the others. The receiver's and the sender's headers include
# their parts (receiver_*, sender_*) after the class.
TRANSFER_HEADERS = ("transfer", "transfer_base", "file_names", "ranges", "posix_files", "json", "receive_dir",
                    "deflate",
                    "partial", "file_source", "receiver", "receiver_offers", "receiver_data", "receiver_status",
                    "sharing",
                    "sender", "sender_control", "sender_data", "sender_frame_size")
# The node: node.hpp includes node_config.hpp, setpoints.hpp and node_context.hpp first and its
# other parts after the class.
NODE_HEADERS = ("node", "node_config", "setpoints", "node_context", "node_receive", "node_files", "node_pipe",
                "node_pump", "dtt_link")
# Links on DJI's SDKs that need the SDK's own header (compiled in tests against DJI's vendored
# headers, tests/vendor/dji/): the node on the Payload SDK's low-speed channel, and on the Onboard
# SDK's DTT (3.x and 4.x).
SDK_HEADERS = ("psdk_link", "osdk_link", "mop_link", "osdk_mop_link")
_SUB_HEADERS = (*RUNTIME_HEADERS, "enums", "messages", "signing", "packets", "sha256", "scheduler", "commands",
                *TRANSFER_HEADERS, *NODE_HEADERS, *SDK_HEADERS, "pipe_link", "udp_link", "udp_forward")
# What the onboard link runtime (commands.hpp, transfer.hpp, node.hpp) is written against: these
# messages with ttctl's ids and CRC_EXTRA (ttctl.wire.contract), and these enums.
LINK_MESSAGES = ("HEARTBEAT", "TT_FILE_OFFER", "TT_FILE_STATUS", "TT_FILE_DATA", "TT_FILE_REQUEST", "TT_ACTION_COMMAND",
                 "TT_LOG", "TT_FILE_DATA_WIDE", "TT_COMMAND_ACK", "TT_FILE_REASON", "TT_FILE_MAP")
LINK_ENUMS = ("TT_FILE_RESULT", "TT_FILE_FLAGS", "TT_RESULT")
# The tablet's control traffic, which the node's rate grants leave room for once heard (as
# proto/endpoint.py's `_control`): commands, set-points, VR poses and controllers.
CONTROL_MESSAGES = ("TT_ACTION_COMMAND", "DJI_POSE_STAMPED", "TT_VR_POSE", "TT_VR_CONTROLLER")


def carries_link(d: Dialect) -> bool:
    """Whether the dialect has the runtime's messages (it includes ttapi.xml), so that the onboard
    link runtime (the node, commands, file transfer) is generated for it."""
    from ..wire.contract import RUNTIME_MESSAGES

    have = {m.name: (m.id, m.crc_extra) for m in d.messages if m.complete}
    enums = {e.name for e in d.enums}
    return all(have.get(n) == RUNTIME_MESSAGES[n] for n in LINK_MESSAGES) and all(e in enums for e in LINK_ENUMS)


def answers_setpoints(d: Dialect) -> bool:
    """Whether the dialect has the tablet's set-points (DJI_POSE_STAMPED, DJI_TOPIC_NAME_SETPOINT),
    so that the node answers them (NodeContext::setpoint())."""
    pose = next((m for m in d.messages if m.name == "DJI_POSE_STAMPED"), None)
    topic = next((e for e in d.enums if e.name == "DJI_TOPIC_NAME"), None)
    return (carries_link(d) and pose is not None and topic is not None
            and topic.entry("DJI_TOPIC_NAME_SETPOINT") is not None
            and {"target_system", "sec", "nsec", "topic_name"} <= {f.name for f in pose.fields})


def plugin_handles(d: Dialect) -> list[Message]:
    """The messages the node's plugin skeleton has a handler for, beside on_command(): those of
    the root dialect the onboard end receives, and the tablet's set-point (DJI_POSE_STAMPED) when
    the node answers set-points, from an included ttapi.xml too (the README fills that handler in)."""
    out = [m for m in receives(d, "onboard") if m.name != "TT_ACTION_COMMAND"]
    pose = d.messages_by_name.get("DJI_POSE_STAMPED")
    if answers_setpoints(d) and pose is not None and pose not in out:
        out = sorted([*out, pose], key=lambda m: m.id)
    return out


def confirms_vr_controller(d: Dialect) -> bool:
    """Whether the node confirms every TT_VR_CONTROLLER with NAMED_VALUE_INT "vrbtn<index>" =
    its packet_num, as ttctl's onboard end does (ttctl.ends.onboard.vr_controller), so that
    `ttctl hmd dump --to` sees its button changes confirmed."""
    fields = {m.name: {f.name: (f.type, f.array_length) for f in m.fields} for m in d.messages}
    vr, named = fields.get("TT_VR_CONTROLLER", {}), fields.get("NAMED_VALUE_INT", {})
    return (carries_link(d) and vr.get("index") == ("uint8_t", 0) and vr.get("packet_num") == ("uint32_t", 0)
            and named.get("name") == ("char", 10) and named.get("value") == ("int32_t", 0)
            and named.get("time_boot_ms") == ("uint32_t", 0))


def namespace(d: Dialect, override: str | None = None) -> str:
    """The C++ namespace of a dialect: `override` (--cpp-namespace, maybe nested: a::b), else
    its identifier, unless that is a keyword or a name the standard library or the runtime
    already uses."""
    if override:
        return override
    ident = dialect_ident(d)
    if ident in CPP_KEYWORDS or ident in C_RESERVED or ident in ("std", "detail", "onboard"):
        return f"{ident}_mav"
    return ident


def folder(d: Dialect, override: str | None = None) -> str:
    """The folder (relative to cpp/) of the dialect's headers: the namespace's path (a::b ->
    a/b) with --cpp-namespace, else the dialect's identifier."""
    return override.replace("::", "/") if override else dialect_ident(d)


def umbrella(d: Dialect, override: str | None = None) -> str:
    """Path (relative to cpp/) of the header that includes everything of the dialect."""
    ident = dialect_ident(d)
    stem = f"{ident}_all" if ident in _SUB_HEADERS else ident
    return f"{folder(d, override)}/{stem}.hpp"


def guard(d: Dialect, part: str, override: str | None = None) -> str:
    base = override.replace("::", "_") if override else dialect_ident(d)
    return f"TTCTL_{base.upper()}_{part.upper()}_HPP"


def cpp_type(f: Field) -> str:
    base = _CPP_TYPES[f.type]
    return f"std::array<{base}, {f.array_length}>" if f.array_length else base


def initializer(f: Field, d: Dialect) -> str:
    """Brace initializer of a field: zero, except mavlink_version (the dialect's version)."""
    return f"{{{d.version}}}" if f.mavlink_version else "{}"


def enum_base(e: Enum) -> str:
    """The smallest unsigned type that holds every value of the enum."""
    top = max((x.value for x in e.entries), default=0)
    for bits in (8, 16, 32):
        if top < 1 << bits:
            return f"std::uint{bits}_t"
    return "std::uint64_t"


def enum_value(e: Enum, value: int) -> str:
    if e.bitmask and value > 9:
        return f"0x{value:X}"
    return str(value)


def _clean(text: str) -> str:
    return " ".join((text or "").split())


def comment(text: str, indent: int = 0, width: int = 100, prefix: str = "/// ") -> str:
    """`text` as //-comment lines (wrapped; no line ends in a backslash, which would splice
    the next source line into the comment)."""
    lead = " " * indent + prefix
    lines = wrap(_clean(text) or "(no description)", max(40, width - len(lead)))
    out = []
    for line in lines:
        line = line.rstrip()
        while line.endswith("\\"):
            line = line[:-1].rstrip()
        out.append((lead + line).rstrip())
    return "\n".join(out)


def field_comment(f: Field, indent: int = 4, d: Dialect | None = None) -> str:
    extra = []
    if f.units:
        extra.append(f"[{f.units}]")
    if f.enum:
        extra.append(f"(enum {enum_class(f.enum, d)})")
    if f.extension:
        extra.append("(extension)")
    return comment(" ".join([f.description or f.name, *extra]), indent)


def enum_class(name: str, d: Dialect | None) -> str:
    """The generated type of the enum called `name` (CamelCase when the dialect lacks it)."""
    got = type_names(d).enums.get(name) if d is not None else None
    return got or camel(name)


def local(m: Message, name: str) -> str:
    """A parameter or local variable name for code inside message `m`'s struct that no field of
    it shadows (-Wshadow): `name`, or `name_` if a field is called that."""
    fields = {f.name for f in m.fields}
    while name in fields:
        name += "_"
    return name


def handler_name(m: Message) -> str:
    return f"on_{m.name.lower()}"


def handler_fields(m: Message, indent: int = 4, d: Dialect | None = None) -> str:
    """A handler's comment lines listing the message's fields: name (type, units, enum) and
    description, in XML order."""
    lines = [" " * indent + "/// Fields of msg:"]
    for f in m.fields:
        notes = [f.declared_type, *([f.units] if f.units else []),
                 *([f"enum {enum_class(f.enum, d)}"] if f.enum else []), *(["extension"] if f.extension else [])]
        head = f"- {f.name} ({', '.join(notes)})"
        text = _clean(f.description)
        lines.extend(comment(f"{head}: {text}" if text else head, indent, prefix="///   ").split("\n"))
    return "\n".join(lines)


def field_kind(f: Field) -> str:
    """How the conformance program presents a field: text (char), float, int; arrays are
    lists of those (except char arrays, which are text)."""
    if f.type == "char":
        return "text"
    return "float" if f.is_float else "int"


def check_names(d: Dialect) -> None:
    """Refuse dialects whose type names would collide with the runtime's (the validator does
    not know about them)."""
    names = [m.name for m in d.messages] + [e.name for e in d.enums]
    clash = sorted({camel(n) for n in names} & RUNTIME_TYPES)
    if clash:
        import jinja2

        raise jinja2.TemplateRuntimeError(
            f"C++: {', '.join(clash)} would collide with the C++ runtime type(s) of the same name; rename the "
            "message or enum")


def _headers(where: str, stems: tuple[str, ...]) -> list[Output]:
    """A header per stem in cpp/<where>/, each from its template."""
    return [Output(f"cpp/{where}/{h}.hpp", f"cpp/{h}.hpp.j2") for h in stems]


class _Cpp:
    name = "cpp"

    def __init__(self, override: str | None = None) -> None:
        self.override = override  # --cpp-namespace; None: from the dialect's identifier

    def outputs(self, d: Dialect) -> list[Output]:
        ident = folder(d, self.override)  # the dialect's identifier, or a/b for --cpp-namespace a::b
        link = [
            Output(f"cpp/{ident}/commands.hpp", "cpp/commands.hpp.j2"),
            *_headers(ident, TRANSFER_HEADERS),
            *_headers(ident, NODE_HEADERS),
            *_headers(ident, SDK_HEADERS),
            Output(f"cpp/{ident}/pipe_link.hpp", "cpp/pipe_link.hpp.j2"),
            Output(f"cpp/{ident}/udp_link.hpp", "cpp/udp_link.hpp.j2"),
        ] if carries_link(d) else []
        return [
            *_headers(ident, RUNTIME_HEADERS),
            Output(f"cpp/{ident}/sha256.hpp", "cpp/sha256.hpp.j2"),
            Output(f"cpp/{ident}/signing.hpp", "cpp/signing.hpp.j2"),
            Output(f"cpp/{ident}/packets.hpp", "cpp/packets.hpp.j2"),
            Output(f"cpp/{ident}/scheduler.hpp", "cpp/scheduler.hpp.j2"),
            *link,
            Output(f"cpp/{ident}/udp_forward.hpp", "cpp/udp_forward.hpp.j2"),
            Output(f"cpp/{ident}/enums.hpp", "cpp/enums.hpp.j2"),
            Output(f"cpp/{ident}/messages.hpp", "cpp/messages.hpp.j2"),
            Output(f"cpp/{umbrella(d, self.override)}", "cpp/umbrella.hpp.j2"),
            Output("cpp/conformance.cpp", "cpp/conformance.cpp.j2"),
            Output("cpp/conformance_json.hpp", "cpp/conformance_json.hpp.j2"),
            Output("cpp/conformance_json_reader.hpp", "cpp/conformance_json_reader.hpp.j2"),
            Output(f"cpp/onboard/{dialect_ident(d)}_plugin.hpp", "cpp/plugin.hpp.j2", skeleton=True),
        ]

    def owned_dirs(self, d: Dialect) -> list[str]:
        return [f"cpp/{folder(d, self.override)}"]

    def globals(self, d: Dialect) -> dict[str, Any]:
        check_names(d)
        return {
            "ns": namespace(d, self.override),
            "link": carries_link(d),
            "setpoints": answers_setpoints(d),
            "plugin_handles": plugin_handles(d),
            "vr_confirm": confirms_vr_controller(d),
            "control_ids": [m.id for m in d.messages if m.name in CONTROL_MESSAGES],
            "folder": folder(d, self.override),
            "umbrella": umbrella(d, self.override),
            "guard": lambda part: guard(d, part, self.override),
            "cpp_type": cpp_type,
            "initializer": lambda f: initializer(f, d),
            "enum_base": enum_base,
            "enum_value": enum_value,
            "comment": comment,
            "field_comment": lambda f, indent=4: field_comment(f, indent, d),
            "handler_name": handler_name,
            "handler_fields": lambda m, indent=4: handler_fields(m, indent, d),
            "local": local,
            "field_kind": field_kind,
        }


LANG = _Cpp()
