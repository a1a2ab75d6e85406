"""Atomic output: the one way twoball puts a file, a collection or a folder in place.

Every writer (report folders, reproduction, exports, renders, plots) works in a
*scratch* entry beside its target and commits it with renames on the same file
system, so a reader sees the earlier complete output or the new complete
output, never a mix and never a partial file:

* :func:`staged_file` -- one file: written as ``scratch/NAME``, then
  ``os.replace`` onto the target (atomic).
* :func:`staged_collection` -- a main file with side entries (XDMF + HDF5, PVD
  + its frames folder): the side entries are moved in first, the main file
  last.  A side entry named by the hash of its content (the PVD frames folder)
  never changes an earlier one, so the main file's replacement is the single
  commit point; a fixed side name (``NAME.h5``) is replaced just before its
  main file, with SIGINT/SIGTERM held back meanwhile (only SIGKILL or a power
  cut in that microsecond window can pair an old main file with a new side file).
* :func:`staged_folder` -- a whole folder (``verify``, ``converge``, ``reproduce``):
  written into a scratch folder with the marker :data:`MARKER`, then exchanged
  with the target in one ``renameat2(RENAME_EXCHANGE)`` (two renames where the
  file system cannot exchange).

Folders twoball writes carry one marker file, :data:`MARKER`: JSON naming the
writer and listing every file it wrote.  An existing target folder is replaced
only if it is empty or holds the marker and nothing but the files it lists; any
other entry (a user's file, a symbolic link) makes :func:`check_folder` raise
:class:`~twoball._common.errors.ParameterError` naming ``out`` and the entry.
A target that is a symbolic link is refused, never followed.

Scratch entries are named ``.NAME.twoball-scratch-PID-TOKEN`` and removed on
every exit path: exceptions and, through
:func:`twoball._common.signals.raise_on_signals` (which turns SIGINT and SIGTERM
into :class:`~twoball._common.signals.Interrupted`), signals; commits and clean-ups
run with signals held back (:func:`deferred_signals`), and once a commit is done a
signal is held until the next work starts (:func:`committed_signals`): a run
signalled while its last output was committed keeps that output whole and still
ends as interrupted (130 / 143, :mod:`twoball.cli.guard`).  Scratch left by a killed
(SIGKILL) process is swept by the next run that writes the same target, once
its process id is gone.

Testing hook: with ``TWOBALL_TEST_PAUSE=STAGE`` in the environment, :func:`pause`
prints ``twoball-test-pause: STAGE`` on standard error at that stage and sleeps
(up to 60 s) so a test can signal the process at a known point.  Stages:
``begin`` (scratch made, nothing written), ``staged`` (all written, nothing
moved), ``commit`` (halfway through the moves, signals held back) and ``pool``
(worker processes started).

Only the standard library is imported: the command line loads this module
before any numerical one.
"""

from __future__ import annotations

import contextlib
import ctypes
import errno
import json
import os
import re
import secrets
import shutil
import sys
from collections.abc import Callable, Iterator, Sequence
from pathlib import Path

from twoball._common.signals import (
    committed_signals,
    deferred_signals,
    pause,
    resume,
    sigterm_raises,
)

MARKER = ".twoball-output"
#: Marker of report folders written by twoball before 0.x; such a folder is
#: replaced only if everything else in it is a file of :data:`LEGACY_FILES`.
LEGACY_MARKER = ".twoball-report"
LEGACY_FILES = frozenset(
    {
        "report.md",
        "results.json",
        "results.csv",
        "summary.csv",
        "checks.csv",
        "eigenvalues.csv",
        "pole.png",
        "eigenvalues.png",
        "energy.png",
        "convergence.png",
    }
)
SCRATCH_TAG = "twoball-scratch"
_NAME_KEEP = 180  # characters of the target's name kept in a scratch name (NAME_MAX 255)


# --------------------------------------------------------------------------- errors
def _parameter_error(param: str, valid: str, got: object) -> Exception:
    from twoball._common.errors import ParameterError

    return ParameterError(param, valid, got)


def _named(error: OSError, target: Path) -> OSError:
    """``error`` re-addressed to the user's target (not the hidden scratch name)."""
    if error.errno is None:
        return error
    return OSError(error.errno, error.strerror or os.strerror(error.errno), str(target))


# --------------------------------------------------------------------------- targets
def _plain_target(path: str | os.PathLike[str], param: str, valid: str) -> Path:
    """``path`` made absolute; refused if it is a symbolic link or its folder is unusable."""
    check_path_type(path, param)
    try:
        return _usable_target(path, param, valid)
    except OSError as error:  # a name or path too long, a loop of links, ...
        reason = error.strerror or str(error)
        shown = os.fspath(path)
        shown = shown if len(shown) <= 200 else shown[:100] + "..." + shown[-60:]
        raise _parameter_error(param, valid + f" ({reason})", shown) from None


def _usable_target(path: str | os.PathLike[str], param: str, valid: str) -> Path:
    out = Path(path).expanduser()
    if out.name in ("", ".", ".."):
        raise _parameter_error(param, valid, str(path))
    if out.is_symlink():
        raise _parameter_error(param, valid + " (not a symbolic link)", str(path))
    out = out.absolute()
    parent = out.parent
    if not parent.is_dir():
        raise _parameter_error(param, valid + " (the folder does not exist)", str(path))
    probe = parent / f".{out.name[:_NAME_KEEP]}.{SCRATCH_TAG}-{os.getpid()}-{secrets.token_hex(4)}"
    try:  # proves the folder writable (permissions, read-only mounts, /proc, name length)
        probe.mkdir(mode=0o700)
        probe.rmdir()
    except OSError as error:
        reason = error.strerror or "not writable"
        raise _parameter_error(
            param, valid + f" (the folder is not writable: {reason})", str(path)
        ) from None
    if (out.exists() or out.is_symlink()) and mount_point(out):
        raise _parameter_error(
            param,
            valid + " (it is a mount point: the output replaces it by a rename, which a "
            "mount point refuses)",
            str(path),
        )
    sweep_stale(out)
    return out


def mount_point(path: Path) -> bool:
    """Whether ``path`` (absolute, existing) is a mount point: a rename cannot replace it.

    :func:`os.path.ismount` sees a file system mounted there; a file or folder
    bind-mounted from the same file system is found in ``/proc/self/mountinfo``.
    """
    if os.path.ismount(path):
        return True
    try:
        real = os.path.join(os.path.realpath(path.parent), path.name)
        with open("/proc/self/mountinfo", encoding="utf-8", errors="replace") as stream:
            for line in stream:
                fields = line.split(" ")
                if len(fields) > 4 and _unescape(fields[4]) == real:
                    return True
    except OSError:  # no /proc: ismount's answer stands
        return False
    return False


def _unescape(text: str) -> str:
    """A mountinfo path: ``\\040`` is a space (octal escapes of space, tab, newline, backslash)."""
    return re.sub(r"\\([0-7]{3})", lambda m: chr(int(m.group(1), 8)), text)


def same_path(a: str | os.PathLike[str], b: str | os.PathLike[str]) -> bool:
    """Whether ``a`` and ``b`` name one file: the same inode, or the same absolute path."""
    first, second = Path(a).expanduser(), Path(b).expanduser()
    with contextlib.suppress(OSError):
        if first.exists() and second.exists():
            return os.path.samefile(first, second)
    return os.path.abspath(first) == os.path.abspath(second)


def check_distinct(
    outputs: dict[str, str | os.PathLike[str] | None],
    inputs: dict[str, object] | None = None,
    labels: dict[str, str] | None = None,
) -> None:
    """Refuse, before any work, two outputs with one path, or an output onto an input.

    ``outputs`` maps each output's parameter (``plot``, ``render``) to its path
    (None: not given); ``inputs`` maps a description (``the input mesh file``)
    to its path (not a path: skipped).  The error names the later output and
    what it collides with (``labels``: how to show an output's name there, e.g.
    its flag).
    """
    labels = labels or {}
    seen: list[tuple[str, Path]] = []
    for what, path in (inputs or {}).items():
        if isinstance(path, str | os.PathLike) and os.fspath(path):
            seen.append((what, Path(path)))
    for name, path in outputs.items():
        if path is None:
            continue
        for what, earlier in seen:
            if same_path(path, earlier):
                raise _parameter_error(name, f"a path other than {what}", os.fspath(path))
        seen.append((f"the output of {labels.get(name, name)}", Path(path)))


def check_path_type(path: object, param: str = "out") -> str | os.PathLike[str]:
    """``path`` itself if it is a str or os.PathLike (else ParameterError naming ``param``)."""
    if isinstance(path, bool) or not isinstance(path, str | os.PathLike):
        from twoball._common.errors import ParameterError

        shown = path if isinstance(path, int | float) else type(path).__name__
        raise ParameterError(param, "a file path (str or os.PathLike)", shown)
    return path


def check_file(path: str | os.PathLike[str], param: str = "out") -> Path:
    """Check, before any work, that a file (or a collection's main file) can be written.

    The folder must exist and be writable; ``path`` may exist (it is replaced)
    but must be neither a folder nor a symbolic link.

    Returns
    -------
    Path
        ``path``, absolute.

    Raises
    ------
    ParameterError
        Naming ``param``, for the one-line command-line error (exit status 2).
    """
    valid = "a file path in an existing, writable folder"
    out = _plain_target(path, param, valid)
    if out.is_dir():
        raise _parameter_error(param, valid + " (it is a folder)", str(path))
    return out


def check_folder(path: str | os.PathLike[str], param: str = "out") -> Path:
    """Check, before any work, that a folder can be written (and replaced) at ``path``.

    ``path`` may be missing, an empty folder, or a folder twoball wrote (it holds
    :data:`MARKER` and only the files listed there); anything else is refused.

    Raises
    ------
    ParameterError
        Naming ``param``; for a folder with foreign content, the first foreign entry.
    """
    valid = "a new or empty folder, or one that twoball wrote, in an existing writable folder"
    out = _plain_target(path, param, valid)
    if out.exists() and not out.is_dir():
        raise _parameter_error(param, valid + " (it is a file)", str(path))
    if out.is_dir():
        foreign = foreign_entry(out)
        if foreign is not None:
            raise _parameter_error(
                param,
                "a new or empty folder, or one that twoball wrote",
                f"{path} (it holds {foreign!r}, which twoball did not write)",
            )
    return out


def _listed_files(folder: Path) -> set[str] | None:
    """The files the folder's marker lists (relative POSIX paths), or None without one."""
    marker = folder / MARKER
    if marker.is_file() and not marker.is_symlink():
        try:
            files = json.loads(marker.read_text(encoding="utf-8"))["files"]
        except (OSError, ValueError, KeyError, TypeError):
            return None
        if isinstance(files, list) and all(isinstance(f, str) for f in files):
            return set(files) | {MARKER}
        return None
    legacy = folder / LEGACY_MARKER
    if legacy.is_file() and not legacy.is_symlink():
        return set(LEGACY_FILES) | {LEGACY_MARKER}
    return None


def _entries(folder: Path) -> Iterator[tuple[str, bool]]:
    """``(relative path, is a real folder)`` of everything below ``folder`` (links not followed)."""
    for root, dirs, files in os.walk(folder, followlinks=False):
        base = Path(root).relative_to(folder)
        for name in sorted(dirs):
            path = Path(root) / name
            yield (base / name).as_posix(), not path.is_symlink()
        for name in sorted(files):
            yield (base / name).as_posix(), False


def foreign_entry(folder: Path) -> str | None:
    """The first entry of ``folder`` twoball did not write, or None if it may be replaced."""
    listed = _listed_files(folder)
    prefixes = {p for f in listed or () for p in _parents(f)}
    for name, is_dir in _entries(folder):
        if listed is None:
            return name
        if is_dir and name in prefixes:
            continue
        if not is_dir and name in listed and not (folder / name).is_symlink():
            continue
        return name
    return None


def _parents(relative: str) -> list[str]:
    parts = relative.split("/")[:-1]
    return ["/".join(parts[: k + 1]) for k in range(len(parts))]


def write_marker(folder: Path, writer: str) -> None:
    """Write :data:`MARKER` into ``folder``: who wrote it and every file below it (sorted)."""
    files = sorted(name for name, is_dir in _entries(folder) if not is_dir and name != MARKER)
    text = json.dumps({"written_by": writer, "files": files}, indent=1) + "\n"
    (folder / MARKER).write_text(text, encoding="utf-8")


# --------------------------------------------------------------------------- scratch
def _scratch_pattern(out: Path) -> re.Pattern[str]:
    return re.compile(rf"\.{re.escape(out.name[:_NAME_KEEP])}\.{SCRATCH_TAG}-(\d+)-[0-9a-f]+")


def _alive(pid: int) -> bool:
    if pid == os.getpid():
        return True
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    return True


def sweep_stale(out: Path) -> list[Path]:
    """Remove scratch of ``out`` left by processes that no longer exist (killed runs)."""
    pattern = _scratch_pattern(out)
    removed = []
    with contextlib.suppress(OSError):
        for entry in out.parent.iterdir():
            match = pattern.fullmatch(entry.name)
            if match and not _alive(int(match.group(1))):
                _remove(entry)
                removed.append(entry)
    return removed


def _remove(path: Path) -> None:
    if path.is_dir() and not path.is_symlink():
        shutil.rmtree(path, ignore_errors=True)
    else:
        with contextlib.suppress(FileNotFoundError):
            path.unlink()


@contextlib.contextmanager
def _scratch_dir(out: Path) -> Iterator[Path]:
    """A fresh scratch folder beside ``out``, removed on every exit path."""
    name = f".{out.name[:_NAME_KEEP]}.{SCRATCH_TAG}-{os.getpid()}-{secrets.token_hex(4)}"
    scratch = out.parent / name
    resume()  # new work after an earlier commit: a signal held since then acts now
    with sigterm_raises():
        try:
            scratch.mkdir(mode=0o700)
        except OSError as error:
            raise _named(error, out) from None
        try:
            pause("begin")
            yield scratch
        except OSError as error:
            raise _named(error, out) from error
        finally:
            with deferred_signals():
                _remove(scratch)


def _public_mode(path: Path, folder: bool) -> None:
    """Permissions a plain ``open``/``mkdir`` would have given (umask applied)."""
    mask = os.umask(0)
    os.umask(mask)
    os.chmod(path, (0o777 if folder else 0o666) & ~mask)


# --------------------------------------------------------------------------- writers
@contextlib.contextmanager
def staged_file(path: str | os.PathLike[str], param: str = "out") -> Iterator[Path]:
    """Yield a scratch path; once the block ends without error, replace ``path`` by it.

    Examples
    --------
    >>> with staged_file("plot.png") as scratch:  # doctest: +SKIP
    ...     figure.savefig(scratch)
    """
    out = check_file(path, param)
    with _scratch_dir(out) as scratch:
        target = scratch / out.name
        yield target
        if not target.is_file():
            raise FileNotFoundError(errno.ENOENT, "the writer wrote no file", str(out))
        pause("staged")
        with committed_signals():  # once replaced, the file stands (see signals)
            pause("commit")
            os.replace(target, out)


@contextlib.contextmanager
def staged_collection(
    path: str | os.PathLike[str],
    param: str = "out",
    retire: Callable[[Path, Sequence[str]], Sequence[Path]] | None = None,
    ours: Callable[[Path], bool] | None = None,
) -> Iterator[Path]:
    """Yield a scratch folder for a main file (named like ``path``) and its side entries.

    Everything the block writes into the scratch folder is moved beside
    ``path``: side entries first, the main file last (the commit point).  A
    side *folder* must carry :data:`MARKER`; if a folder of its name is already
    there with the same content it is kept (content-addressed names), otherwise
    it is refused unless twoball wrote it.  ``retire(out, new_names)`` lists
    earlier entries the new main file no longer refers to; they are removed
    after the commit (only folders twoball wrote, files as given).  An existing
    side *file* is replaced only if ``ours(existing)`` says twoball wrote it
    (checked again just before the moves; without ``ours`` it is replaced).
    """
    out = check_file(path, param)
    with _scratch_dir(out) as scratch:
        yield scratch
        if not (scratch / out.name).is_file():
            raise FileNotFoundError(errno.ENOENT, "the writer wrote no main file", str(out))
        sides = sorted(p.name for p in scratch.iterdir() if p.name != out.name)
        for name in sides:  # refuse before anything moves
            _check_side(scratch / name, out.parent / name, param, ours)
        old = list(retire(out, sides)) if retire is not None else []
        pause("staged")
        with committed_signals():
            for k, name in enumerate(sides):
                _move_side(scratch / name, out.parent / name)
                if k == len(sides) // 2:
                    pause("commit")
            if not sides:
                pause("commit")
            os.replace(scratch / out.name, out)
            for entry in old:
                if entry.name not in sides and (not entry.is_dir() or foreign_entry(entry) is None):
                    _remove(entry)


def _check_side(
    new: Path, existing: Path, param: str, ours: Callable[[Path], bool] | None = None
) -> None:
    if existing.is_symlink():
        raise _parameter_error(
            param, "a path whose side files are not symbolic links", f"{existing}"
        )
    if new.is_dir():
        if not (new / MARKER).is_file():  # pragma: no cover - a writer's mistake
            raise RuntimeError(f"side folder {new.name} has no {MARKER}")
        if existing.exists() and (not existing.is_dir() or foreign_entry(existing) is not None):
            raise _parameter_error(
                param,
                "a path whose side folder is new or one that twoball wrote",
                f"{existing}",
            )
    elif existing.is_dir():
        raise _parameter_error(param, "a path whose side files are not folders", f"{existing}")
    elif ours is not None and existing.exists() and not ours(existing):
        raise _parameter_error(
            param, "a path whose side files are missing or ones twoball wrote", f"{existing}"
        )


def _same_tree(a: Path, b: Path) -> bool:
    names_a = [n for n in _entries(a)]
    if names_a != [n for n in _entries(b)]:
        return False
    for name, is_dir in names_a:
        if not is_dir and (a / name).read_bytes() != (b / name).read_bytes():
            return False
    return True


def _move_side(new: Path, existing: Path) -> None:
    if new.is_dir():
        if existing.is_dir():
            if _same_tree(new, existing):
                return  # content-addressed: the earlier copy is this one
            _exchange(new, existing)
            return
        _public_mode(new, folder=True)
        os.rename(new, existing)
    else:
        os.replace(new, existing)


@contextlib.contextmanager
def staged_folder(
    path: str | os.PathLike[str], param: str = "out", writer: str = "twoball"
) -> Iterator[Path]:
    """Yield a scratch folder; once the block ends without error, it replaces ``path``.

    :data:`MARKER` (with ``writer`` and the list of files) is added before the
    commit.  ``path`` is checked first with :func:`check_folder` and again just
    before the exchange, so a user's file added meanwhile is not lost either.
    """
    out = check_folder(path, param)
    with _scratch_dir(out) as scratch:
        yield scratch
        write_marker(scratch, writer)
        _public_mode(scratch, folder=True)
        pause("staged")
        check_folder(out, param)
        with committed_signals():
            pause("commit-folder")  # not "commit": the folder's files may be committed within
            if out.is_dir():
                _exchange(scratch, out)  # scratch now holds the old folder: removed on exit
            else:
                os.rename(scratch, out)


@contextlib.contextmanager
def scratch_folder(path: str | os.PathLike[str], param: str = "out") -> Iterator[Path]:
    """A private working folder beside the folder ``path``, removed on every exit path.

    For a writer that commits its folder more than once (:func:`staged_folder`
    for each state worth keeping, e.g. every finished part of a reproduction)
    and keeps what it has made so far here between the commits.
    """
    out = check_folder(path, param)
    with _scratch_dir(out) as scratch:
        yield scratch


_RENAME_EXCHANGE = 2
_AT_FDCWD = -100


def _exchange(new: Path, out: Path) -> None:
    """Swap the folders ``new`` and ``out`` atomically (Linux ``renameat2``), else two renames.

    Afterwards ``new`` holds the previous content of ``out``.
    """
    if sys.platform.startswith("linux"):
        try:
            libc = ctypes.CDLL(None, use_errno=True)
            renameat2 = libc.renameat2
        except (OSError, AttributeError):
            renameat2 = None
        if renameat2 is not None:
            result = renameat2(
                _AT_FDCWD, os.fsencode(new), _AT_FDCWD, os.fsencode(out), _RENAME_EXCHANGE
            )
            if result == 0:
                return
            code = ctypes.get_errno()
            if code not in (errno.EINVAL, errno.ENOSYS, errno.EOPNOTSUPP):
                raise OSError(code, os.strerror(code), str(out))
    hold = new.with_name(new.name + "0")  # still a scratch name (hex tail): swept if stranded
    os.rename(out, hold)
    try:
        os.rename(new, out)
    except BaseException:
        os.rename(hold, out)
        raise
    os.rename(hold, new)


__all__ = [
    "LEGACY_MARKER",
    "MARKER",
    "check_file",
    "check_folder",
    "deferred_signals",
    "foreign_entry",
    "scratch_folder",
    "staged_collection",
    "staged_file",
    "staged_folder",
    "sweep_stale",
    "write_marker",
]
