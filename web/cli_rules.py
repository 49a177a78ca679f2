"""The native command line's rules for a scene file and an output path (src/scene/scene_json.cpp readSceneFile,
src/io/output_path.cpp resolveOutput and refuseOverwritingInput, src/io/atomic_file.cpp PendingOutput), with
its messages word for word, for web.sh render: the browser's `shadelab render` reads and writes files as
`shadelab render` does. Keep the two in step
(tests/web/browser_test.cpp RenderScript* compare them).
"""
import errno
import os
import stat
import tempfile

MAX_SCENE_BYTES = 16 << 20  # kMaxSceneBytes


class InputError(Exception):
    """Bad input: exit 2."""


class RuntimeFailure(Exception):
    """A failure while working: exit 1."""


def printable(text):
    """shadelab's printable(): control bytes, C1 controls and bytes that are not valid UTF-8 as \\xNN."""
    data = os.fsencode(text) if isinstance(text, str) else bytes(text)
    out = []
    for ch in data.decode('utf-8', errors='surrogateescape'):
        code = ord(ch)
        if 0x20 <= code < 0x7f:
            out.append(ch)
        elif 0xdc80 <= code <= 0xdcff:  # a byte that is not valid UTF-8
            out.append('\\x%02x' % (code - 0xdc00))
        elif code < 0x20 or code == 0x7f or 0x80 <= code <= 0x9f or 0xd800 <= code <= 0xdfff:
            out.extend('\\x%02x' % b for b in ch.encode('utf-8', errors='surrogatepass'))
        else:
            out.append(ch)
    return ''.join(out)


def quoted(path):
    return '"' + printable(path) + '"'


def read_scene(path):
    """The scene's text: a regular file of at most 16 MiB, or - for standard input."""
    from_stdin = path == '-'
    name = 'standard input' if from_stdin else printable(path)

    def cannot_read(reason):
        raise InputError(name + ': cannot read scene file: ' + reason)

    fd = 0
    if not from_stdin:
        try:
            st = os.stat(path)
        except OSError as e:
            cannot_read(os.strerror(e.errno))
        if stat.S_ISDIR(st.st_mode):
            cannot_read('it is a directory')
        if not stat.S_ISREG(st.st_mode):
            cannot_read('it is ' + ('a FIFO' if stat.S_ISFIFO(st.st_mode) else 'not a regular file') +
                        '; a scene is a regular file, or - to read standard input')
        try:
            fd = os.open(path, os.O_RDONLY | os.O_CLOEXEC | os.O_NOCTTY | os.O_NONBLOCK)
        except OSError as e:
            cannot_read(os.strerror(e.errno))
        if not stat.S_ISREG(os.fstat(fd).st_mode):
            os.close(fd)
            cannot_read('it is not a regular file; a scene is a regular file, or - to read standard input')
    chunks, size = [], 0
    try:
        while True:
            chunk = os.read(fd, 65536)
            if not chunk:
                break
            chunks.append(chunk)
            size += len(chunk)
            if size > MAX_SCENE_BYTES:
                raise InputError(name + ': cannot read scene file: larger than 16 MiB; not a scene file')
    except OSError as e:
        cannot_read('read error: ' + os.strerror(e.errno))
    finally:
        if not from_stdin:
            os.close(fd)
    return b''.join(chunks)


def _descriptor_named_by(path):
    # std::filesystem's lexically_normal keeps a trailing separator ("/dev/fd/1/" and "/dev/fd/1/." stay
    # "/dev/fd/1/"), so the command line names no descriptor there and then finds "/dev/fd/1" is no
    # folder; os.path.normpath drops it, and "/dev/fd/1/" was taken for descriptor 1.
    if path.endswith('/') or path.endswith('/.'):
        return None
    text = os.path.normpath(path)
    named = {'/dev/stdin': 0, '/dev/stdout': 1, '/dev/stderr': 2}
    if text in named:
        return named[text]
    for prefix in ('/dev/fd/', '/proc/self/fd/', '/proc/thread-self/fd/', '/proc/%d/fd/' % os.getpid()):
        number = text[len(prefix):] if text.startswith(prefix) else ''
        if number.isdigit() and len(number) <= 9 and number.isascii():
            return int(number)
    return None


def _writable(path, folder, name):
    if os.path.exists(path) and not os.access(path, os.W_OK, effective_ids=True):
        mode = '%04o' % (os.stat(path).st_mode & 0o7777)
        raise InputError('%s: %s exists and you may not write it (mode %s: %s); make it writable or choose '
                         'another path' % (name, quoted(path), mode, os.strerror(errno.EACCES)))
    if not os.access(folder, os.W_OK | os.X_OK, effective_ids=True):
        raise InputError('%s: cannot create files in the folder %s (%s): the output is written beside its '
                         'name and renamed; choose another folder' % (name, quoted(folder), os.strerror(errno.EACCES)))


def resolve_output(user_path, name='--out'):
    """('stdout'|'descriptor'|'through'|'regular', path or fd), decided before any work."""
    if not user_path:
        raise InputError(name + ': the output path is empty; give a file name such as out.png, or - for '
                         'standard output')
    if user_path == '-':
        return 'stdout', 1
    path = user_path
    for _ in range(41):
        if os.path.isabs(path):
            fd = _descriptor_named_by(path)
            if fd is not None:
                return _descriptor(user_path, fd, name)
        try:
            st = os.lstat(path)
        except OSError:
            st = None
        if st is not None and stat.S_ISLNK(st.st_mode):
            folder = os.path.dirname(path) or '.'
            try:
                fst = os.stat(folder)
                sticky = fst.st_mode & stat.S_ISVTX and fst.st_mode & stat.S_IWOTH
                if sticky and st.st_uid not in (os.geteuid(), fst.st_uid):
                    raise InputError('%s: %s is a symbolic link of uid %d in the sticky world-writable folder %s, '
                                     'which the kernel (fs.protected_symlinks) would not follow for you; remove '
                                     'the link or choose another path' % (name, quoted(path), st.st_uid,
                                                                          quoted(folder)))
            except FileNotFoundError:
                pass
            target = os.readlink(path)
            path = target if os.path.isabs(target) else os.path.join(os.path.dirname(path), target)
            continue
        try:
            st = os.stat(path)
        except OSError as e:
            if e.errno not in (errno.ENOENT, errno.ENOTDIR):
                raise InputError('%s: cannot use %s: %s' % (name, quoted(user_path), os.strerror(e.errno)))
            break
        if stat.S_ISREG(st.st_mode):
            _writable(path, os.path.dirname(path) or '.', name)
            return 'regular', path
        if stat.S_ISCHR(st.st_mode) or stat.S_ISFIFO(st.st_mode):
            return 'through', path
        kind = ('a directory' if stat.S_ISDIR(st.st_mode) else 'a block device' if stat.S_ISBLK(st.st_mode)
                else 'a socket' if stat.S_ISSOCK(st.st_mode) else 'not a file')
        raise InputError('%s: %s is %s; give a file name such as out.png, a character device or FIFO, or - '
                         'for standard output' % (name, quoted(user_path), kind))
    else:
        raise InputError('%s: %s is a loop of symbolic links; give a path that ends at a file'
                         % (name, quoted(user_path)))
    folder = os.path.dirname(path) or '.'
    try:
        folder_mode = os.stat(folder).st_mode
    except OSError as e:
        if e.errno == errno.ENOTDIR:  # FILE/sub/x.png: a regular file on the way, not a missing folder
            raise InputError('%s: a part of %s is a file, not a folder; choose a path inside a folder'
                             % (name, quoted(folder))) from None
        raise InputError('%s: the folder %s does not exist; create it first or choose another path'
                         % (name, quoted(folder))) from None
    if not stat.S_ISDIR(folder_mode):
        raise InputError('%s: %s is a file, not a folder; choose a path inside a folder' % (name, quoted(folder)))
    _writable(path, folder, name)
    return 'regular', path


def refuse_overwriting_input(output, field, input_path):
    """refuseOverwritingInput: the output is the input file under any name, as stat() follows it (a link,
    /dev/stdout or /dev/fd/N open on it, as in `--out /dev/stdout >> scene.json`)."""
    if not output or not input_path or input_path == '-':
        return
    try:
        if output == '-':  # standard output redirected onto the input: `--out - >> scene.json`
            a = os.fstat(1)
            if not stat.S_ISREG(a.st_mode):
                return
        else:
            a = os.stat(output)
        b = os.stat(input_path)
    except (OSError, ValueError):
        return
    if (a.st_dev, a.st_ino) == (b.st_dev, b.st_ino):
        shown = '- (standard output)' if output == '-' else quoted(output)
        raise InputError('%s: %s is the input file %s; writing it would destroy the input: choose another output '
                         'path' % (field, shown, quoted(input_path)))


def _descriptor(user_path, fd, name):
    try:
        import fcntl
        flags = fcntl.fcntl(fd, fcntl.F_GETFL)
    except OSError:
        raise InputError('%s: %s names descriptor %d, which is not open; give a file name, or - for standard '
                         'output' % (name, quoted(user_path), fd)) from None
    if flags & os.O_ACCMODE == os.O_RDONLY:
        raise InputError('%s: %s names descriptor %d, which is open for reading only; give a file name, or - '
                         'for standard output' % (name, quoted(user_path), fd))
    if stat.S_ISDIR(os.fstat(fd).st_mode):
        raise InputError('%s: %s names descriptor %d, which is a directory; give a file name, or - for standard '
                         'output' % (name, quoted(user_path), fd))
    return 'descriptor', fd


def _write_all(fd, data):
    view = memoryview(data)
    while view:
        view = view[os.write(fd, view):]


def write_output(target, data, what='PNG'):
    """Puts `data` where resolve_output said: a regular file through a temporary file renamed over it
    (its mode and owner kept, a new file's mode from umask), a device or FIFO written through (never
    created or truncated), a descriptor written to."""
    kind, where = target
    shown = 'standard output' if kind == 'stdout' else str(where) if kind == 'descriptor' else where

    def failed(reason):
        return RuntimeFailure('cannot write %s %s: %s' % (what, quoted(shown), reason))

    try:
        if kind in ('stdout', 'descriptor'):
            _write_all(where, data)
            return
        if kind == 'through':
            fd = os.open(where, os.O_WRONLY | os.O_NOCTTY | os.O_CLOEXEC)
            try:
                if not (stat.S_ISCHR(os.fstat(fd).st_mode) or stat.S_ISFIFO(os.fstat(fd).st_mode)):
                    raise failed('it is no longer a device or FIFO; not writing through it')
                _write_all(fd, data)
            finally:
                os.close(fd)
            return
    except OSError as e:
        raise failed(os.strerror(e.errno)) from None
    folder = os.path.dirname(where) or '.'
    try:
        fd, temp = tempfile.mkstemp(prefix='.shadelab-', dir=folder)
    except OSError as e:
        raise failed('cannot create a temporary file in %s: %s' % (quoted(folder), os.strerror(e.errno))) from None
    try:
        mask = os.umask(0)
        os.umask(mask)
        mode = 0o666 & ~mask
        if os.path.exists(where):
            old = os.stat(where)
            mode = old.st_mode & 0o7777
            try:
                os.fchown(fd, old.st_uid, old.st_gid)
            except PermissionError:
                if os.geteuid() == 0:
                    raise
        os.fchmod(fd, mode)
        _write_all(fd, data)
        os.fsync(fd)
        os.close(fd)
        fd = -1
        os.replace(temp, where)
    except OSError as e:
        if fd >= 0:
            os.close(fd)
        if os.path.lexists(temp):
            os.unlink(temp)
        raise failed(os.strerror(e.errno)) from None
    except BaseException:
        if fd >= 0:
            os.close(fd)
        if os.path.lexists(temp):
            os.unlink(temp)
        raise
