// A small WASI (wasi_snapshot_preview1) host for running hider-render.wasm as a command: arguments,
// an in-memory directory preopened as "/" (the program's working directory), stdout and stderr
// captured as text, and the exit status. Each run gets a fresh instance, so nothing survives a run
// (not even a trap). Calls the module makes that are not implemented here return ENOSYS.

const ERRNO = { success: 0, badf: 8, exist: 20, inval: 28, isdir: 31, noent: 44, nosys: 52, notdir: 54, spipe: 70 };
const FILETYPE = { character_device: 2, directory: 3, regular_file: 4 };
const OFLAGS = { creat: 1, directory: 2, excl: 4, trunc: 8 };
const PREOPEN_FD = 3;

/** Thrown by proc_exit to unwind out of the module. */
class WasiExit {
  constructor(code) { this.code = code; }
}

/**
 * Runs `entry` ("_start" or another export) of a compiled WASI module.
 * files: Map name -> Uint8Array (read and written in place; new files appear in it).
 * Returns {code, stdout, stderr, trap}: code is the exit status (0 when the export returned),
 * trap the message of a WebAssembly trap (code 134 then).
 */
export function runWasi(module, { args = [], files = new Map(), entry = "_start" } = {}) {
  const utf8 = new TextEncoder();
  const argBytes = args.map((a) => utf8.encode(a + "\0"));
  const out = { 1: [], 2: [] };
  const open = new Map();  // fd -> {name, pos}
  let nextFd = PREOPEN_FD + 1;
  let memory = null;
  const view = () => new DataView(memory.buffer);
  const bytes = () => new Uint8Array(memory.buffer);
  const readString = (ptr, len) => new TextDecoder().decode(bytes().slice(ptr, ptr + len));
  const fileOf = (fd) => open.get(fd);

  // Visits the iovec array (buf, len pairs of u32).
  function iovecs(ptr, count, visit) {
    const v = view();
    let total = 0;
    for (let i = 0; i < count; ++i) {
      const buf = v.getUint32(ptr + 8 * i, true);
      const len = v.getUint32(ptr + 8 * i + 4, true);
      const n = visit(buf, len);
      total += n;
      if (n < len) break;
    }
    return total;
  }

  function writeFilestat(ptr, type, size) {
    const v = view();
    for (let i = 0; i < 64; i += 8) v.setBigUint64(ptr + i, 0n, true);
    v.setUint8(ptr + 16, type);
    v.setBigUint64(ptr + 24, 1n, true);            // nlink
    v.setBigUint64(ptr + 32, BigInt(size), true);  // size
  }

  const wasi = {
    args_sizes_get(argcPtr, bufSizePtr) {
      view().setUint32(argcPtr, argBytes.length, true);
      view().setUint32(bufSizePtr, argBytes.reduce((n, a) => n + a.length, 0), true);
      return ERRNO.success;
    },
    args_get(argvPtr, bufPtr) {
      let p = bufPtr;
      argBytes.forEach((a, i) => {
        view().setUint32(argvPtr + 4 * i, p, true);
        bytes().set(a, p);
        p += a.length;
      });
      return ERRNO.success;
    },
    environ_sizes_get(countPtr, sizePtr) {
      view().setUint32(countPtr, 0, true);
      view().setUint32(sizePtr, 0, true);
      return ERRNO.success;
    },
    environ_get() { return ERRNO.success; },
    fd_prestat_get(fd, ptr) {
      if (fd !== PREOPEN_FD) return ERRNO.badf;
      view().setUint8(ptr, 0);           // preopen type: directory
      view().setUint32(ptr + 4, 1, true);  // name length of "/"
      return ERRNO.success;
    },
    fd_prestat_dir_name(fd, ptr, len) {
      if (fd !== PREOPEN_FD) return ERRNO.badf;
      if (len >= 1) bytes()[ptr] = 0x2f;  // "/"
      return ERRNO.success;
    },
    fd_fdstat_get(fd, ptr) {
      let type;
      if (fd <= 2) type = FILETYPE.character_device;
      else if (fd === PREOPEN_FD) type = FILETYPE.directory;
      else if (open.has(fd)) type = FILETYPE.regular_file;
      else return ERRNO.badf;
      const v = view();
      v.setUint8(ptr, type);
      v.setUint16(ptr + 2, 0, true);                  // fdflags
      v.setBigUint64(ptr + 8, 0xffffffffn, true);     // rights: all
      v.setBigUint64(ptr + 16, 0xffffffffn, true);
      return ERRNO.success;
    },
    fd_fdstat_set_flags() { return ERRNO.success; },
    path_open(dirFd, dirFlags, pathPtr, pathLen, oflags, rightsBase, rightsInheriting, fdFlags, fdPtr) {
      if (dirFd !== PREOPEN_FD) return ERRNO.badf;
      const name = readString(pathPtr, pathLen).replace(/^(\.\/)+/, "");
      if (name === "" || name === ".") return (oflags & OFLAGS.directory) ? ERRNO.nosys : ERRNO.isdir;
      if (oflags & OFLAGS.directory) return ERRNO.notdir;
      if (!files.has(name)) {
        if (!(oflags & OFLAGS.creat)) return ERRNO.noent;
        files.set(name, new Uint8Array(0));
      } else if (oflags & OFLAGS.excl) {
        return ERRNO.exist;
      }
      if (oflags & OFLAGS.trunc) files.set(name, new Uint8Array(0));
      const fd = nextFd++;
      open.set(fd, { name, pos: 0, append: (fdFlags & 1) !== 0 });
      view().setUint32(fdPtr, fd, true);
      return ERRNO.success;
    },
    path_filestat_get(dirFd, flags, pathPtr, pathLen, ptr) {
      if (dirFd !== PREOPEN_FD) return ERRNO.badf;
      const name = readString(pathPtr, pathLen).replace(/^(\.\/)+/, "");
      if (name === "" || name === ".") { writeFilestat(ptr, FILETYPE.directory, 0); return ERRNO.success; }
      if (!files.has(name)) return ERRNO.noent;
      writeFilestat(ptr, FILETYPE.regular_file, files.get(name).length);
      return ERRNO.success;
    },
    path_unlink_file(dirFd, pathPtr, pathLen) {
      if (dirFd !== PREOPEN_FD) return ERRNO.badf;
      const name = readString(pathPtr, pathLen).replace(/^(\.\/)+/, "");
      return files.delete(name) ? ERRNO.success : ERRNO.noent;
    },
    fd_close(fd) {
      if (!open.delete(fd)) return fd <= PREOPEN_FD ? ERRNO.success : ERRNO.badf;
      return ERRNO.success;
    },
    fd_read(fd, iovPtr, iovCount, nreadPtr) {
      const f = fileOf(fd);
      if (!f) return fd === 0 ? (view().setUint32(nreadPtr, 0, true), ERRNO.success) : ERRNO.badf;
      const data = files.get(f.name);
      const n = iovecs(iovPtr, iovCount, (buf, len) => {
        const chunk = data.subarray(f.pos, Math.min(data.length, f.pos + len));
        bytes().set(chunk, buf);
        f.pos += chunk.length;
        return chunk.length;
      });
      view().setUint32(nreadPtr, n, true);
      return ERRNO.success;
    },
    fd_write(fd, iovPtr, iovCount, nwrittenPtr) {
      let n;
      if (fd === 1 || fd === 2) {
        n = iovecs(iovPtr, iovCount, (buf, len) => { out[fd].push(bytes().slice(buf, buf + len)); return len; });
      } else {
        const f = fileOf(fd);
        if (!f) return ERRNO.badf;
        n = iovecs(iovPtr, iovCount, (buf, len) => {
          let data = files.get(f.name);
          if (f.append) f.pos = data.length;
          if (f.pos + len > data.length) {  // grow by doubling, keep the logical size in `size`
            const grown = new Uint8Array(Math.max(f.pos + len, data.length * 2));
            grown.set(data);
            grown.size = Math.max(data.size ?? data.length, f.pos + len);
            data = grown;
          } else if (data.size !== undefined) {
            data.size = Math.max(data.size, f.pos + len);
          }
          data.set(bytes().subarray(buf, buf + len), f.pos);
          files.set(f.name, data);
          f.pos += len;
          return len;
        });
      }
      view().setUint32(nwrittenPtr, n, true);
      return ERRNO.success;
    },
    fd_seek(fd, offset, whence, newOffsetPtr) {
      const f = fileOf(fd);
      if (!f) return fd <= 2 ? ERRNO.spipe : ERRNO.badf;
      const data = files.get(f.name);
      const size = data.size ?? data.length;
      const base = whence === 0 ? 0 : whence === 1 ? f.pos : size;
      const pos = base + Number(offset);
      if (pos < 0) return ERRNO.inval;
      f.pos = pos;
      view().setBigUint64(newOffsetPtr, BigInt(pos), true);
      return ERRNO.success;
    },
    path_remove_directory() { return ERRNO.nosys; },
    proc_exit(code) { throw new WasiExit(code); },
  };

  const imports = { wasi_snapshot_preview1: {} };
  for (const imp of WebAssembly.Module.imports(module)) {
    if (imp.kind !== "function") continue;
    const fn = imp.module === "wasi_snapshot_preview1" ? wasi[imp.name] : undefined;
    imports[imp.module] ??= {};
    imports[imp.module][imp.name] = fn ?? (() => ERRNO.nosys);
  }
  const instance = new WebAssembly.Instance(module, imports);
  memory = instance.exports.memory;
  let code = 0, trap = null;
  try {
    instance.exports[entry]();
  } catch (e) {
    if (e instanceof WasiExit) {
      code = e.code;
    } else if (e instanceof WebAssembly.RuntimeError || e instanceof RangeError) {
      code = 134;
      trap = String(e.message || e);
    } else {
      throw e;
    }
  }
  // Trim grown files to their written size.
  for (const [name, data] of files) {
    if (data.size !== undefined) files.set(name, data.slice(0, data.size));
  }
  const text = (chunks) => new TextDecoder().decode(concat(chunks));
  return { code, stdout: text(out[1]), stderr: text(out[2]), trap };
}

function concat(chunks) {
  const all = new Uint8Array(chunks.reduce((n, c) => n + c.length, 0));
  let p = 0;
  for (const c of chunks) { all.set(c, p); p += c.length; }
  return all;
}
