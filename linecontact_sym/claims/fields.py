"""Validation of the fields of a claims file: each value has the type the
format says (a single string is not a list of names, ``true`` is not a
number), and the file itself is a bounded UTF-8 text file."""
from __future__ import annotations

from pathlib import Path


from ..core.conversion import exact_number
from ..core.errors import ClaimError
from ..parsing import SYMBOLS, parse_number

def where_text(source, label=None, fld=None):
    out = str(source)
    if label:
        out += f": claim {label!r}"
    if fld:
        out += f": {fld}"
    return out


def parse_range(val, where):
    if not (isinstance(val, (list, tuple)) and len(val) == 2):
        raise ClaimError(f"{where}: a range is [low, high], got {val!r}")
    lo, hi = (float(number_field(v, where)) for v in val)
    if not lo <= hi:   # [v, v] fixes the value v
        raise ClaimError(f"{where}: empty range [{lo}, {hi}]")
    return (lo, hi)


def check_sign(name, value, syms, where):
    """A sampling range or special value of a symbol declared positive must be
    > 0 (the work of adhesion gamma: >= 0); x may have any sign."""
    sym = syms.get(name) or SYMBOLS.get(name)
    if sym is None or not sym.is_positive or name == "x":
        return
    v = float(value)
    if not (v > 0 or (name == "gamma" and v == 0)):
        raise ClaimError(f"{where}: {name} is a positive quantity; got {value} (sampling there would "
                         f"check the claim outside its domain)")


def number_field(v, where):
    if isinstance(v, bool):
        raise ClaimError(f"{where}: expected a number, got {v!r}")
    if not isinstance(v, str):
        return exact_number(v)       # the one converter (floats: their shortest decimal)
    return parse_number(v, where)    # the one reader of typed numbers (plain number, then an expression)


def text_field(v, where, required=False):
    if v is None and not required:
        return ""
    if not isinstance(v, str) or (required and not v.strip()):
        raise ClaimError(f"{where}: expected a text")
    return v


#: the largest claims file read (bytes): a claims file is a page of text
MAX_FILE_BYTES = 1_000_000


def read_text_file(path: Path) -> str:
    """The text of a claims file: a regular UTF-8 file of at most
    :data:`MAX_FILE_BYTES` bytes (never a device, a FIFO or a directory)."""
    if not path.is_file():
        raise ClaimError(f"{path}: not a regular file (a claims file is a TOML text file)")
    try:
        with open(path, "rb") as fh:
            raw = fh.read(MAX_FILE_BYTES + 1)
    except OSError as exc:
        raise ClaimError(f"{path}: cannot be read: {exc.strerror or exc}") from None
    if len(raw) > MAX_FILE_BYTES:
        raise ClaimError(f"{path}: larger than {MAX_FILE_BYTES} bytes; a claims file is a page of text")
    try:
        return raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise ClaimError(f"{path}: not UTF-8 text (byte {exc.start}): is it a claims file?") from None


def typed_field(table, key, types, where, default=None):
    """``table[key]`` checked to be of ``types`` (a bool is never an int)."""
    v = table.get(key, default)
    if v is default and key not in table:
        return v
    ok = isinstance(v, types) and not (isinstance(v, bool) and bool not in (types if isinstance(types, tuple)
                                                                               else (types,)))
    if not ok:
        names = " or ".join(t.__name__ for t in (types if isinstance(types, tuple) else (types,)))
        names = names.replace("str", "a string").replace("list", "a list").replace("dict", "a table")
        raise ClaimError(f"{where}: {key} must be {names}, got {type(v).__name__} {v!r}")
    return v


def names_field(table, key, where):
    """A list of symbol names (a single string is refused: it is not a list)."""
    v = typed_field(table, key, list, where, [])
    if not all(isinstance(n, str) for n in v):
        raise ClaimError(f"{where}: {key} must be a list of names, got {v!r}")
    return v


