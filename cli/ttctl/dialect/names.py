"""Identifier rules shared by the validator and the code generators.

The validator refuses every name that one of the generators could not emit
verbatim, so the generators never need to mangle names.
"""

from __future__ import annotations

import re

IDENTIFIER_RE = re.compile(r"[A-Za-z_][A-Za-z0-9_]*\Z")


def _words(text: str) -> frozenset[str]:
    return frozenset(text.split())


PYTHON_KEYWORDS = _words(
    """False None True and as assert async await break class continue def del elif else except
    finally for from global if import in is lambda nonlocal not or pass raise return try while
    with yield"""
)

CPP_KEYWORDS = _words(
    """alignas alignof and and_eq asm auto bitand bitor bool break case catch char char8_t
    char16_t char32_t class compl concept const consteval constexpr constinit const_cast
    continue co_await co_return co_yield decltype default delete do double dynamic_cast else
    enum explicit export extern false float for friend goto if inline int long mutable
    namespace new noexcept not not_eq nullptr operator or or_eq private protected public
    register reinterpret_cast requires return short signed sizeof static static_assert
    static_cast struct switch template this thread_local throw true try typedef typeid
    typename union unsigned using virtual void volatile wchar_t while xor xor_eq"""
)

JAVA_KEYWORDS = _words(
    """abstract assert boolean break byte case catch char class const continue default do
    double else enum extends final finally float for goto if implements import instanceof int
    interface long native new package private protected public return short static strictfp
    super switch synchronized this throw throws transient try void volatile while true false
    null _ var yield record sealed permits"""
)

# g++ compiles C++ as its GNU dialect unless told -std=c++NN: these are keywords there too.
GNU_CPP_KEYWORDS = _words("typeof")

# Java's contextual keywords: type names they cannot be, but fields, parameters and constants
# they can (javac --release 8, 11 and 17 accept `int var`, `this.yield = yield`...).
JAVA_CONTEXTUAL = _words("var yield record sealed permits")

# Names that are not keywords but that break generated C++ when used verbatim: object-like
# macros of the C library headers the generated code (or its conformance program) includes, and
# of g++ itself in its default GNU modes. (Function-like macros such as assert and offsetof
# expand only before a '(', which never follows a field or entry name in generated code.)
C_MACROS: dict[str, str] = {
    "NULL": "a macro of <cstddef> and <cstring>, which the generated C++ includes",
    "errno": "a macro of <cerrno>, which the generated C++ includes",
    "EOF": "a macro of <cstdio>, which the generated conformance program includes",
    "stdin": "a macro of <cstdio> (an expression in most C libraries), which the generated conformance "
             "program includes",
    "stdout": "a macro of <cstdio> (an expression in most C libraries), which the generated conformance "
              "program includes",
    "stderr": "a macro of <cstdio> (an expression in most C libraries), which the generated conformance "
              "program includes",
    "linux": "a macro g++ predefines (as 1) in its default GNU modes",
    "unix": "a macro g++ predefines (as 1) in its default GNU modes",
}
C_RESERVED = frozenset(C_MACROS)
# Java's implicit java.lang types that a generated class of the same name would shadow inside
# the generated package.
JAVA_RESERVED_TYPES = _words(
    """Object String Class Integer Long Short Byte Float Double Boolean Character Math System
    Thread Runnable Override Deprecated Exception RuntimeException Error Enum Record Iterable
    Number Void"""
)

# What each generated language refuses as an identifier (the generators emit Python, C++ and
# Java; a name is checked as they spell it, see spelled()).
LANGUAGE_KEYWORDS: dict[str, frozenset[str]] = {
    "Python": PYTHON_KEYWORDS,
    "C++": CPP_KEYWORDS,
    "C++ as g++ compiles it by default (-std=gnu++17)": GNU_CPP_KEYWORDS - CPP_KEYWORDS,
    "Java": JAVA_KEYWORDS - JAVA_CONTEXTUAL,
}

# Types the generated runtimes define next to the message and enum types (Python package,
# C++ namespace): a message or enum whose CamelCase name is one of these would clash.
RUNTIME_TYPE_NAMES = _words(
    """Message MessageInfo Parser ParserStats Encoder Signing DecodeError BasicPacketizer DecodeStatus
    Dispatcher Frame IsBitmask Packetizer Plugin Sha256 SignatureCheck PacketReceiver ReceiverStats
    Outbox NullOutbox"""
)

# Members every generated message class/struct defines; a field of the same name would
# shadow them. Kept in one place so the templates and the validator agree.
GENERATED_MESSAGE_MEMBERS = _words(
    """MSG_ID NAME CRC_EXTRA PAYLOAD_LENGTH MIN_LENGTH FIELDS ENUMS TYPES pack pack_payload unpack
    unpack_payload to_dict from_dict encode decode msgid crc_extra self cls get_msgId get_type
    get_seq get_srcSystem get_srcComponent get_signed"""
)

# Names the generated Java code uses as the first part of a qualified name (java.util.Arrays,
# Long.toHexString): Java resolves such a name to a field or constant of the class first, so a
# field (message classes) or an entry (enum classes) of that name breaks them.
JAVA_QUALIFIERS_IN_MESSAGES: dict[str, str] = {
    "java": "the generated Java message class calls java.util.Arrays, which a field named java hides",
}
JAVA_QUALIFIERS_IN_ENUMS: dict[str, str] = {
    "java": "the generated Java enum class calls java.util.Arrays, which an entry named java hides",
    "Long": "the generated Java enum class calls Long.toHexString, which an entry named Long hides",
}


def camel(name: str) -> str:
    """UPPER_SNAKE or lower_snake to CamelCase: GPS_RAW_INT -> GpsRawInt, GPS2_RAW -> Gps2Raw."""
    return name.title().replace("_", "")


def lower_camel(name: str) -> str:
    """lower_snake to lowerCamel, keeping capitals already there: time_boot_ms -> timeBootMs,
    speed_x and speedX -> speedX."""
    if "_" not in name:
        return name[:1].lower() + name[1:]
    first, *rest = name.split("_")
    return first[:1].lower() + first[1:] + "".join([p[:1].upper() + p[1:] for p in rest])


_KEYWORD_LANGS: dict[str, list[str]] = {}
for _lang, _kws in LANGUAGE_KEYWORDS.items():
    for _w in _kws:
        _KEYWORD_LANGS.setdefault(_w, []).append(_lang)

# Every word that keyword_hits() or C_MACROS refuses: a name outside it needs no closer look.
RESERVED_WORDS = frozenset(_KEYWORD_LANGS) | C_RESERVED


def keyword_hits(name: str) -> list[str]:
    """Generated languages in which `name` (exactly as written) is a keyword."""
    return _KEYWORD_LANGS.get(name, [])


def spelled(name: str, type_name: bool) -> str:
    """The identifier the generators emit for a name: message and enum names become CamelCase
    types (GPS_RAW_INT -> GpsRawInt in Python, C++ and Java); fields and enum entries keep their
    XML spelling. (The handlers' on_<name> methods are prefixed: never a keyword.)"""
    return camel(name) if type_name else name


def reserved_identifier(name: str) -> str | None:
    """Why `name` is reserved for the implementation in C/C++, or None."""
    if "__" in name:
        return "identifiers containing '__' are reserved in C++ (and in C when leading)"
    if name[:1] == "_" and name[1:2].isupper():
        return "identifiers starting with '_' and a capital letter are reserved in C and C++"
    return None
