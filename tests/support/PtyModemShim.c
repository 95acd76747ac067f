/* Test-only LD_PRELOAD shim that lets Debian's libserialport 0.1.1 open a
 * pseudo-terminal, so the tests can drive the real libserialport path
 * against the probe emulator.
 *
 * libserialport refuses a pty in two places:
 *  - sp_get_port_by_name() looks up /sys/class/tty/<name> with lstat() and
 *    readlink(); ptys (/dev/pts/N) have no such entry. The shim answers for
 *    /sys/class/tty/pts/N as if it were a symlink to a virtual tty device.
 *  - sp_open() and the configuration calls use the modem-line ioctls
 *    (TIOCMGET, TIOCMSET, TIOCMBIS, TIOCMBIC), which a pty rejects. The
 *    shim lets those succeed when the kernel says "not a tty"-type errors,
 *    reporting DSR, CTS and CD asserted, as a null-modem cable would.
 * Every other call goes straight to the C library.
 */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <stdarg.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <unistd.h>

static const char kPtsClassPrefix[] = "/sys/class/tty/pts/";
static const char kPtsClassTarget[] = "../../devices/virtual/tty/pts";

static int isPtsClassEntry(const char* path)
{
    return path && strncmp(path, kPtsClassPrefix, sizeof kPtsClassPrefix - 1) == 0;
}

/* libserialport 0.1.1 was built before glibc exported lstat itself. */
int __lxstat(int version, const char* path, struct stat* buffer)
{
    if (isPtsClassEntry(path)) {
        memset(buffer, 0, sizeof *buffer);
        buffer->st_mode = S_IFLNK | 0777;
        return 0;
    }
    int (*real)(int, const char*, struct stat*) = (int (*)(int, const char*, struct stat*))dlsym(RTLD_NEXT, "__lxstat");
    return real(version, path, buffer);
}

ssize_t readlink(const char* path, char* buffer, size_t size)
{
    if (isPtsClassEntry(path)) {
        const size_t length = sizeof kPtsClassTarget - 1;
        const size_t copied = length < size ? length : size;
        memcpy(buffer, kPtsClassTarget, copied);
        return (ssize_t)copied;
    }
    ssize_t (*real)(const char*, char*, size_t) = (ssize_t(*)(const char*, char*, size_t))dlsym(RTLD_NEXT, "readlink");
    return real(path, buffer, size);
}

int ioctl(int fd, unsigned long request, ...)
{
    va_list arguments;
    va_start(arguments, request);
    void* argument = va_arg(arguments, void*);
    va_end(arguments);

    int (*real)(int, unsigned long, ...) = (int (*)(int, unsigned long, ...))dlsym(RTLD_NEXT, "ioctl");
    const int result = real(fd, request, argument);
    const int modemLine = request == TIOCMGET || request == TIOCMSET || request == TIOCMBIS || request == TIOCMBIC;
    if (result == 0 || !modemLine || (errno != EINVAL && errno != ENOTTY) || !isatty(fd)) return result;
    if (request == TIOCMGET) *(int*)argument = TIOCM_DSR | TIOCM_CTS | TIOCM_CD;
    return 0;
}
