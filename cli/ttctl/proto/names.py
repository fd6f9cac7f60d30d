"""The one set of rules for file names on the link, shared by every end: a sender refuses
before sending what a receiver would refuse, with the same words.

A name is a relative path of UTF-8 components separated by `/`:
- 1..223 bytes in all (the offer's metadata holds 255 bytes: the SHA-256's 32, then the name);
- no empty, `.` or `..` component, no leading `/`, no backslash;
- no NUL, control, format or undecodable characters;
- no component longer than 255 bytes (what Linux allows), and not the receiver's own
  `.ttctl-partial` folder at the top.

What a name means at a particular receiver (a file that exists, a parent that is a file, a
quota) is that receiver's business; storage.py checks it when the offer arrives.
"""

from __future__ import annotations

import unicodedata

SHA_LEN = 32
META_MAX = 255
MAX_NAME_BYTES = META_MAX - SHA_LEN  # 223
PARTIAL_DIR = ".ttctl-partial"


class Refused(Exception):
    """An offer or request that will not be taken; `code` is a TT_FILE_RESULT name suffix
    (NAME, EXISTS, QUOTA, BUSY, NOT_FOUND, REQUEST_REFUSED) and `reason` says why, in words."""

    def __init__(self, code: str, reason: str) -> None:
        super().__init__(reason)
        self.code = code
        self.reason = reason


def encoded(name: str) -> bytes:
    return name.encode("utf-8", "surrogateescape")


def check_name(name: str) -> str:
    """The name, if it is one a receiver may take; Refused('NAME', why) otherwise."""
    if not name:
        raise Refused("NAME", "the name is empty")
    raw = encoded(name)
    if len(raw) > MAX_NAME_BYTES:
        raise Refused("NAME", f"the name is {len(raw)} bytes of UTF-8; at most {MAX_NAME_BYTES} are allowed")
    if "\x00" in name:
        raise Refused("NAME", "the name contains a NUL character")
    if any(unicodedata.category(c) in ("Cc", "Cf", "Cs") for c in name):
        raise Refused("NAME", "the name contains control or undecodable characters")
    if "\\" in name:
        raise Refused("NAME", "the name contains a backslash")
    if name.startswith("/"):
        raise Refused("NAME", "absolute paths are not allowed")
    parts = name.split("/")
    if any(p in ("", ".", "..") for p in parts):
        raise Refused("NAME", "the name has an empty, '.' or '..' component")
    if parts[0] == PARTIAL_DIR:
        raise Refused("NAME", f"{PARTIAL_DIR} is reserved for the receiver's partial files")
    if any(len(encoded(p)) > 255 for p in parts):
        raise Refused("NAME", "a path component is longer than 255 bytes")
    return name


__all__ = ["MAX_NAME_BYTES", "PARTIAL_DIR", "SHA_LEN", "Refused", "check_name", "encoded"]
