// A store whose disk turns read-only while it is being written, for tests
// that run as root (where chmod does not stop a write) and without the
// privilege to remount a file system: an SQLite VFS, made the default for
// the process while it lives, that passes everything to the real "unix" VFS
// until failWrites() — from then on every write fails as the kernel's
// EROFS makes SQLite's own writes fail (SQLITE_IOERR_WRITE, errno EROFS).
#pragma once

#include <sqlite3.h>

#include <atomic>
#include <cerrno>
#include <stdexcept>

namespace tactiscope::testing {

class ReadOnlyAfterVfs {
public:
    ReadOnlyAfterVfs()
    {
        s_real = sqlite3_vfs_find("unix");
        if (!s_real) throw std::runtime_error("no unix VFS");
        m_vfs = *s_real;
        m_vfs.zName = "tactiscope-read-only-after";
        m_vfs.szOsFile = static_cast<int>(sizeof(File)) + s_real->szOsFile;
        m_vfs.xOpen = &open;
        s_failing = false;
        sqlite3_vfs_register(&m_vfs, 1);
    }
    ~ReadOnlyAfterVfs()
    {
        sqlite3_vfs_unregister(&m_vfs);
        sqlite3_vfs_register(s_real, 1);
    }
    ReadOnlyAfterVfs(const ReadOnlyAfterVfs&) = delete;
    ReadOnlyAfterVfs& operator=(const ReadOnlyAfterVfs&) = delete;

    void failWrites() { s_failing = true; }

private:
    // Our file: its methods, then the real VFS's file right behind it.
    struct File {
        sqlite3_file base;
        sqlite3_file* real() { return reinterpret_cast<sqlite3_file*>(this + 1); }
    };

    static sqlite3_file* real(sqlite3_file* file) { return reinterpret_cast<File*>(file)->real(); }

    static int open(sqlite3_vfs*, sqlite3_filename name, sqlite3_file* file, int flags, int* outFlags)
    {
        auto* ours = reinterpret_cast<File*>(file);
        const int code = s_real->xOpen(s_real, name, ours->real(), flags, outFlags);
        ours->base.pMethods = code == SQLITE_OK ? &s_methods : nullptr;
        return code;
    }

    static int write(sqlite3_file* file, const void* data, int amount, sqlite3_int64 offset)
    {
        if (s_failing) {
            errno = EROFS;
            return SQLITE_IOERR_WRITE;
        }
        return real(file)->pMethods->xWrite(real(file), data, amount, offset);
    }

    // Everything else goes to the real file as it is.
    static int close(sqlite3_file* f) { return real(f)->pMethods->xClose(real(f)); }
    static int read(sqlite3_file* f, void* d, int n, sqlite3_int64 o)
    {
        return real(f)->pMethods->xRead(real(f), d, n, o);
    }
    static int truncate(sqlite3_file* f, sqlite3_int64 n) { return real(f)->pMethods->xTruncate(real(f), n); }
    static int sync(sqlite3_file* f, int flags) { return real(f)->pMethods->xSync(real(f), flags); }
    static int fileSize(sqlite3_file* f, sqlite3_int64* n) { return real(f)->pMethods->xFileSize(real(f), n); }
    static int lock(sqlite3_file* f, int l) { return real(f)->pMethods->xLock(real(f), l); }
    static int unlock(sqlite3_file* f, int l) { return real(f)->pMethods->xUnlock(real(f), l); }
    static int checkReservedLock(sqlite3_file* f, int* r) { return real(f)->pMethods->xCheckReservedLock(real(f), r); }
    static int fileControl(sqlite3_file* f, int op, void* a) { return real(f)->pMethods->xFileControl(real(f), op, a); }
    static int sectorSize(sqlite3_file* f) { return real(f)->pMethods->xSectorSize(real(f)); }
    static int deviceCharacteristics(sqlite3_file* f) { return real(f)->pMethods->xDeviceCharacteristics(real(f)); }
    static int shmMap(sqlite3_file* f, int region, int size, int extend, void volatile** p)
    {
        return real(f)->pMethods->xShmMap(real(f), region, size, extend, p);
    }
    static int shmLock(sqlite3_file* f, int offset, int n, int flags)
    {
        return real(f)->pMethods->xShmLock(real(f), offset, n, flags);
    }
    static void shmBarrier(sqlite3_file* f) { real(f)->pMethods->xShmBarrier(real(f)); }
    static int shmUnmap(sqlite3_file* f, int deleteFlag) { return real(f)->pMethods->xShmUnmap(real(f), deleteFlag); }
    static int fetch(sqlite3_file* f, sqlite3_int64 o, int n, void** p)
    {
        return real(f)->pMethods->xFetch(real(f), o, n, p);
    }
    static int unfetch(sqlite3_file* f, sqlite3_int64 o, void* p) { return real(f)->pMethods->xUnfetch(real(f), o, p); }

    static inline sqlite3_vfs* s_real = nullptr;
    static inline std::atomic<bool> s_failing = false;
    static inline const sqlite3_io_methods s_methods = {3,
                                                        close,
                                                        read,
                                                        write,
                                                        truncate,
                                                        sync,
                                                        fileSize,
                                                        lock,
                                                        unlock,
                                                        checkReservedLock,
                                                        fileControl,
                                                        sectorSize,
                                                        deviceCharacteristics,
                                                        shmMap,
                                                        shmLock,
                                                        shmBarrier,
                                                        shmUnmap,
                                                        fetch,
                                                        unfetch};
    sqlite3_vfs m_vfs{};
};

}  // namespace tactiscope::testing
