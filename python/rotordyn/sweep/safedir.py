"""File operations inside one sweep directory that a hostile co-user of the directory cannot
redirect (issue 21).

The directory is opened once (``O_DIRECTORY``) and every operation is relative to that
descriptor, so renaming or replacing the directory's path later changes nothing. Inside it:

* a file is written to a fresh temporary name (``_tmp-<stem>-<random>``, created
  ``O_CREAT|O_EXCL|O_NOFOLLOW``: a planted file or symlink of that name makes the creation
  fail instead of being written through), written through that descriptor, then renamed over
  the final name (``rename`` replaces a symlink there, it never follows it);
* a file is read with ``O_NOFOLLOW|O_NONBLOCK`` and must be a regular file (a symlink, a
  FIFO or a device is refused before a byte is read);
* the lock is ``flock`` on ``_lock`` opened ``O_NOFOLLOW``: the kernel drops it when its
  holder dies, so there is never a stale lock to take over.
"""

from __future__ import annotations

import errno
import fcntl
import json
import os
import secrets
import stat
import time

TMP = "_tmp-"
_RD = os.O_RDONLY | os.O_NOFOLLOW | os.O_NONBLOCK | os.O_CLOEXEC
_NEW = os.O_WRONLY | os.O_CREAT | os.O_EXCL | os.O_NOFOLLOW | os.O_CLOEXEC


class NotRegular(OSError):
    """A name in the directory that is a symlink or not a regular file."""


def _step(name: str) -> None:
    """A no-op between the steps of taking the lock (tests inject delays here)."""


def write_all(fd: int, data: bytes) -> None:
    """os.write until every byte is written (a short write is not an error)."""
    view = memoryview(data)
    while view:
        n = os.write(fd, view)
        view = view[n:]


class SafeDir:
    """One directory, opened by descriptor; names are plain entries of it (no separator)."""

    def __init__(self, path):
        self.path = os.fspath(path)
        self.fd = os.open(self.path, os.O_RDONLY | os.O_DIRECTORY | os.O_CLOEXEC)

    def close(self) -> None:
        if self.fd is not None:
            os.close(self.fd)
            self.fd = None

    @staticmethod
    def _plain(name: str) -> str:
        if not name or "/" in name or "\0" in name or name in (".", ".."):
            raise NotRegular(errno.EINVAL, f"{name!r} is not a plain file name")
        return name

    # -- reading -------------------------------------------------------------------------
    def lstat(self, name: str):
        """os.lstat of the entry, or None if it does not exist."""
        try:
            return os.stat(self._plain(name), dir_fd=self.fd, follow_symlinks=False)
        except FileNotFoundError:
            return None

    def open_regular(self, name: str) -> int:
        """A read descriptor of a regular file; NotRegular for a symlink or anything else."""
        try:
            fd = os.open(self._plain(name), _RD, dir_fd=self.fd)
        except OSError as exc:
            if exc.errno == errno.ELOOP:
                raise NotRegular(errno.ELOOP, f"{name} is a symlink") from None
            raise
        st = os.fstat(fd)
        if not stat.S_ISREG(st.st_mode):
            os.close(fd)
            raise NotRegular(errno.EINVAL, f"{name} is not a regular file")
        return fd

    def read(self, name: str, expect_size: int | None = None) -> bytes:
        """The bytes of a regular file (``expect_size``: refused before reading if the size
        differs)."""
        fd = self.open_regular(name)
        try:
            size = os.fstat(fd).st_size
            if expect_size is not None and size != expect_size:
                raise NotRegular(errno.EINVAL, f"{name} has {size} bytes, the log says "
                                               f"{expect_size}")
            chunks, n = [], 0
            while True:
                b = os.read(fd, max(1 << 16, size - n + 1))
                if not b:
                    break
                chunks.append(b)
                n += len(b)
            return b"".join(chunks)
        finally:
            os.close(fd)

    def names(self) -> list[str]:
        return os.listdir(self.fd)

    # -- writing -------------------------------------------------------------------------
    def create_tmp(self, stem: str) -> tuple[int, str]:
        """(write descriptor, name) of a new, unpredictably named temporary file."""
        for _ in range(64):
            name = f"{TMP}{stem}-{secrets.token_hex(8)}"
            try:
                return os.open(name, _NEW, 0o666, dir_fd=self.fd), name
            except FileExistsError:
                continue
        raise FileExistsError(errno.EEXIST, f"no free temporary name for {stem}")

    def rename(self, src: str, dst: str) -> None:
        os.rename(self._plain(src), self._plain(dst), src_dir_fd=self.fd, dst_dir_fd=self.fd)

    def unlink(self, name: str) -> None:
        """Remove an entry (a symlink itself, never its target); missing is fine."""
        try:
            os.unlink(self._plain(name), dir_fd=self.fd)
        except FileNotFoundError:
            pass

    def write_atomic(self, name: str, data: bytes, *, durable: bool = False,
                     keep_open: bool = False) -> int | None:
        """Write ``data`` to a fresh temporary file, then rename it to ``name``. With
        ``keep_open`` the descriptor (positioned at the end) is returned for appending."""
        fd, tmp = self.create_tmp(name.lstrip("_"))
        try:
            write_all(fd, data)
            if durable:
                os.fsync(fd)
            self.rename(tmp, name)
            if durable:
                os.fsync(self.fd)
        except BaseException:
            os.close(fd)
            self.unlink(tmp)
            raise
        if keep_open:
            return fd
        os.close(fd)
        return None

    # -- the lock --------------------------------------------------------------------------
    def lock(self, name: str, me: dict, is_stale) -> tuple[int | None, dict | None]:
        """Take an exclusive ``flock`` on ``name`` and write ``me`` (JSON) into it.

        Returns (descriptor, None) when held, or (None, holder) when another process holds
        it (holder: its pid and host as written in the file, or as far as known).
        ``is_stale(content)`` decides on a lock file without the flock marker (written by a
        driver of an older version, which used a link lock and may still run): False keeps
        it (refused as held).
        """
        for _ in range(20):
            fd = os.open(self._plain(name), os.O_RDWR | os.O_CREAT | os.O_NOFOLLOW |
                         os.O_NONBLOCK | os.O_CLOEXEC, 0o666, dir_fd=self.fd)
            try:
                if not stat.S_ISREG(os.fstat(fd).st_mode):
                    raise NotRegular(errno.EINVAL, f"{name} is not a regular file")
                _step("opened")
                try:
                    fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
                except BlockingIOError:
                    return None, self._holder(fd)
                _step("locked")
                # the previous holder may have removed the file between our open and our
                # flock (it unlinks while holding the lock): then we hold a lock on a file
                # nobody else will open; start again on the current one
                cur, own = self.lstat(name), os.fstat(fd)
                if cur is None or (cur.st_dev, cur.st_ino) != (own.st_dev, own.st_ino):
                    os.close(fd)
                    fd = None
                    continue
                old = _content(fd)
                if old and not old.get("flock") and not is_stale(old):
                    fcntl.flock(fd, fcntl.LOCK_UN)
                    return None, old
                _step("write")
                try:
                    os.ftruncate(fd, 0)
                    os.pwrite(fd, json.dumps({**me, "flock": True}).encode(), 0)
                except OSError:
                    self.unlink(name)  # (still held: nobody else has it) no lock left
                    raise
                held, fd = fd, None
                return held, None
            finally:
                if fd is not None:
                    os.close(fd)
        raise OSError(errno.EAGAIN, f"{name} kept being replaced while locking")

    @staticmethod
    def _holder(fd: int) -> dict:
        """The holder's identity; it writes it right after taking the lock, so wait a
        moment for it."""
        t0 = time.monotonic()
        while True:
            c = _content(fd)
            if c.get("flock") or time.monotonic() - t0 > 3.0:
                return c
            time.sleep(0.05)

    def unlock(self, name: str, fd: int) -> None:
        """Remove the lock file while still holding it, then release it."""
        try:
            self.unlink(name)
        except OSError:
            pass
        os.close(fd)


def _content(fd: int) -> dict:
    try:
        c = json.loads(os.pread(fd, 4096, 0) or b"{}")
    except (OSError, ValueError):
        return {}
    return c if isinstance(c, dict) else {}
