#!/usr/bin/env bash
# Writes docker/seccomp-sandbox.json: the container's seccomp profile for slamsweep's sandbox.
# Docker's default profile refuses the system calls bubblewrap is made of (unshare and clone with
# namespace flags, mount, pivot_root, setns) to anything without CAP_SYS_ADMIN, so no SLAM program
# could be isolated inside the container. This profile allows every system call of the C library's
# list except those no benchmark needs and that reach outside a container's namespaces: loading
# kernel code, rebooting, setting the clock, swap, accounting, quotas, the kernel log and keyring,
# raw I/O ports, BPF, perf events, userfaultfd, file handles (the classic container escape) and the
# new mount API (bubblewrap uses mount(2)). Anything not listed (a system call newer than this list)
# is refused with EPERM.
# Usage: docker/make-seccomp-profile.sh [UNISTD_HEADER]   (regenerate after a libc/kernel header update)
set -euo pipefail
header=${1:-/usr/include/x86_64-linux-gnu/asm/unistd_64.h}
out=$(cd "$(dirname "$0")" && pwd)/seccomp-sandbox.json
denied=(
  init_module finit_module delete_module kexec_load kexec_file_load reboot
  settimeofday clock_settime clock_adjtime adjtimex
  swapon swapoff acct quotactl quotactl_fd syslog vhangup lookup_dcookie nfsservctl
  iopl ioperm bpf perf_event_open userfaultfd
  add_key request_key keyctl
  open_by_handle_at name_to_handle_at
  fsopen fsconfig fsmount fspick open_tree move_mount mount_setattr
  uselib create_module get_kernel_syms query_module
)
[[ -r "$header" ]] || { echo "make-seccomp-profile: cannot read $header (linux-libc-dev)" >&2; exit 1; }
names=$(sed -n 's/^#define __NR_\([a-z0-9_]*\) [0-9]*$/\1/p' "$header" | sort -u)
deny_pattern="^($(IFS='|'; echo "${denied[*]}"))\$"
allowed=$(grep -Ev "$deny_pattern" <<<"$names")
{
  echo '{'
  echo '  "defaultAction": "SCMP_ACT_ERRNO",'
  echo '  "defaultErrnoRet": 1,'
  echo '  "archMap": [{"architecture": "SCMP_ARCH_X86_64", "subArchitectures": ["SCMP_ARCH_X86", "SCMP_ARCH_X32"]},'
  echo '              {"architecture": "SCMP_ARCH_AARCH64", "subArchitectures": ["SCMP_ARCH_ARM"]}],'
  echo '  "syscalls": ['
  echo '    {'
  echo '      "names": ['
  mapfile -t allowed_list <<<"$allowed"
  printf '        "%s",\n' "${allowed_list[@]}" | sed '$ s/,$//'
  echo '      ],'
  echo '      "action": "SCMP_ACT_ALLOW"'
  echo '    }'
  echo '  ]'
  echo '}'
} > "$out"
echo "make-seccomp-profile: $(wc -l <<<"$allowed") system calls allowed -> $out"
