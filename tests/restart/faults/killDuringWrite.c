/*---------------------------------------------------------------------------*\
  mpmLbmFoam: coupled material point / lattice Boltzmann soil-water solver
-------------------------------------------------------------------------------
Description
    A fault for tests, loaded with LD_PRELOAD: the process kills itself
    (SIGKILL, as the operating system's out-of-memory killer or a batch
    system would) when it opens for writing the Nth file whose path
    contains a given text, i.e. in the middle of writing a time folder.

    MPMLBM_KILL_PATH    text the path must contain, e.g. "/0.0125/"
    MPMLBM_KILL_AT      N: the Nth such file (1 = the first)

    libstdc++'s file streams open through fopen64; fopen and open are
    covered for other writers.
\*---------------------------------------------------------------------------*/

#define _GNU_SOURCE
#include <dlfcn.h>
#include <fcntl.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static int matched = 0;

static void maybeKill(const char* path, int writing)
{
    const char* text = getenv("MPMLBM_KILL_PATH");
    const char* at = getenv("MPMLBM_KILL_AT");
    if (!writing || !text || !at || !path || !strstr(path, text))
    {
        return;
    }
    if (++matched >= atoi(at))
    {
        kill(getpid(), SIGKILL);
    }
}

static int modeWrites(const char* mode)
{
    return mode && (strchr(mode, 'w') || strchr(mode, 'a'));
}

FILE* fopen64(const char* path, const char* mode)
{
    static FILE* (*real)(const char*, const char*) = NULL;
    if (!real)
    {
        real = (FILE* (*)(const char*, const char*))dlsym(RTLD_NEXT, "fopen64");
    }
    maybeKill(path, modeWrites(mode));
    return real(path, mode);
}

FILE* fopen(const char* path, const char* mode)
{
    static FILE* (*real)(const char*, const char*) = NULL;
    if (!real)
    {
        real = (FILE* (*)(const char*, const char*))dlsym(RTLD_NEXT, "fopen");
    }
    maybeKill(path, modeWrites(mode));
    return real(path, mode);
}

int open(const char* path, int flags, ...)
{
    static int (*real)(const char*, int, ...) = NULL;
    if (!real)
    {
        real = (int (*)(const char*, int, ...))dlsym(RTLD_NEXT, "open");
    }
    mode_t mode = 0;
    if (flags & O_CREAT)
    {
        va_list ap;
        va_start(ap, flags);
        mode = va_arg(ap, mode_t);
        va_end(ap);
    }
    maybeKill(path, (flags & (O_WRONLY | O_RDWR)) != 0);
    return real(path, flags, mode);
}
