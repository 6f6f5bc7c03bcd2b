// An LD_PRELOAD shim that makes the disk fail, as a file system that fills
// up does: from the N-th call on (FAULT_AT=N), every write to a regular file
// under FAULT_DIR fails with ENOSPC; or every fsync there with EIO, or every
// rename into it with ENOSPC (FAULT_OP = write | fsync | rename). With
// FAULT_AT=0 nothing fails and the calls are only counted: at exit the count
// is appended to FAULT_COUNT_FILE, so a test knows how many points of failure
// a run has. Children (gnuplot) inherit it; their stdio writes go through
// glibc's internal calls and are not intercepted.
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/uio.h>
#include <unistd.h>

static long calls = 0;

static const char* env(const char* name) {
  const char* v = getenv(name);
  return v ? v : "";
}

static int watched_op(const char* op) { return strcmp(env("FAULT_OP")[0] ? env("FAULT_OP") : "write", op) == 0; }

// A regular file under FAULT_DIR (resolved through /proc/self/fd).
static int watched_fd(int fd) {
  const char* dir = env("FAULT_DIR");
  if (!dir[0]) return 0;
  struct stat st;
  if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) return 0;
  char link[64], path[PATH_MAX];
  snprintf(link, sizeof link, "/proc/self/fd/%d", fd);
  const ssize_t n = readlink(link, path, sizeof path - 1);
  if (n <= 0) return 0;
  path[n] = '\0';
  return strncmp(path, dir, strlen(dir)) == 0;
}

static int watched_path(const char* p) {
  const char* dir = env("FAULT_DIR");
  char resolved[PATH_MAX];
  if (!dir[0] || !realpath(".", resolved)) return 0;
  char full[2 * PATH_MAX];
  if (p[0] == '/')
    snprintf(full, sizeof full, "%s", p);
  else
    snprintf(full, sizeof full, "%s/%s", resolved, p);
  return strncmp(full, dir, strlen(dir)) == 0;
}

// Counts a watched call; true if it must fail.
static int fails(void) {
  ++calls;
  const long at = atol(env("FAULT_AT"));
  return at > 0 && calls >= at;
}

__attribute__((destructor)) static void report(void) {
  const char* file = env("FAULT_COUNT_FILE");
  if (!file[0]) return;
  FILE* f = fopen(file, "a");
  if (!f) return;
  fprintf(f, "%ld\n", calls);
  fclose(f);
}

typedef ssize_t (*write_fn)(int, const void*, size_t);
typedef ssize_t (*pwrite_fn)(int, const void*, size_t, off_t);
typedef ssize_t (*writev_fn)(int, const struct iovec*, int);
typedef int (*fsync_fn)(int);
typedef int (*rename_fn)(const char*, const char*);
#define REAL(name, type)    \
  static type real_##name; \
  if (!real_##name) real_##name = (type)dlsym(RTLD_NEXT, #name)

ssize_t write(int fd, const void* buf, size_t n) {
  REAL(write, write_fn);
  if (watched_op("write") && watched_fd(fd) && fails()) {
    errno = ENOSPC;
    return -1;
  }
  return real_write(fd, buf, n);
}

ssize_t pwrite(int fd, const void* buf, size_t n, off_t off) {
  REAL(pwrite, pwrite_fn);
  if (watched_op("write") && watched_fd(fd) && fails()) {
    errno = ENOSPC;
    return -1;
  }
  return real_pwrite(fd, buf, n, off);
}

ssize_t pwrite64(int fd, const void* buf, size_t n, off_t off) { return pwrite(fd, buf, n, off); }

ssize_t writev(int fd, const struct iovec* iov, int count) {
  REAL(writev, writev_fn);
  if (watched_op("write") && watched_fd(fd) && fails()) {
    errno = ENOSPC;
    return -1;
  }
  return real_writev(fd, iov, count);
}

int fsync(int fd) {
  REAL(fsync, fsync_fn);
  if (watched_op("fsync") && watched_fd(fd) && fails()) {
    errno = EIO;
    return -1;
  }
  return real_fsync(fd);
}

int rename(const char* from, const char* to) {
  REAL(rename, rename_fn);
  if (watched_op("rename") && watched_path(to) && fails()) {
    errno = ENOSPC;
    return -1;
  }
  return real_rename(from, to);
}
