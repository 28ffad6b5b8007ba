#!/usr/bin/env python3
"""Where the firmware's instructions go, function by function, under QEMU.

Runs the instruction-budget image (boards/common/semihosting/bench_main.cpp,
built by `cmake --build BUILD --target firmware_benchmark_cortex_m`) twice on
the synthetic test stream, with N and 2N frames, logging every translated
block and every block executed (qemu -d in_asm,exec,nochain), and prints the
difference per function divided by N: the instructions one more frame costs,
set-up and the kernel bank's configuration cancelled out. The benchmark calls
the columns and kernels phases once on their own and once inside the step,
so their functions appear twice per frame (column_profile, camera_outputs,
half the divisions); the observer phase's do not.

Needs qemu-system-arm and the build's cross images; Python 3, no packages.
"""
import argparse
import collections
import os
import shutil
import subprocess
import sys
import tempfile

# cpu -> the cross image's folder and the MPS2 model that runs it (as benchmark.cmake).
VARIANTS = {
    "cortex-m0plus": ("qemu-m0plus", "mps2-an385"),
    "cortex-m3": ("qemu-m3", "mps2-an385"),
    "cortex-m4": ("qemu-m4", "mps2-an386"),
}


def fail(msg):
    print(f"qemu-profile: error: {msg}", file=sys.stderr)
    sys.exit(1)


def size_arg(text):
    try:
        w, h = (int(v) for v in text.lower().split("x"))
    except ValueError:
        raise argparse.ArgumentTypeError(f"'{text}' is not WxH (e.g. 40x30)")
    if not (1 <= w <= 640 and 1 <= h <= 480):
        raise argparse.ArgumentTypeError(f"'{text}': width 1..640 and height 1..480")
    return w, h


def bounded_int(lo, hi):
    def parse(text):
        try:
            n = int(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"'{text}' is not a whole number")
        if not lo <= n <= hi:
            raise argparse.ArgumentTypeError(f"{n}: must be {lo}..{hi}")
        return n
    return parse


def profile(qemu, machine, image, stream_name, cpu, workdir):
    """Instructions executed per function symbol over one run of the image."""
    cmd = [qemu, "-M", machine, "-icount", "shift=0", "-nographic", "-monitor", "none", "-serial", "none",
           "-semihosting-config", f"enable=on,target=native,arg=bench,arg={stream_name},arg={cpu}",
           "-kernel", image, "-d", "in_asm,exec,nochain"]
    sizes = {}  # translated block (host pointer) -> its guest instructions
    totals = collections.Counter()
    pending = None
    with subprocess.Popen(cmd, cwd=workdir, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                          errors="replace") as p:
        for line in p.stderr:  # QEMU's log goes to standard error without -D
            if line.startswith("IN:"):
                pending = 0
            elif pending is not None and line.startswith("0x"):
                pending += 1
            elif line.startswith("Trace"):
                parts = line.split()
                block = parts[2]
                if pending is not None:
                    sizes[block] = pending
                    pending = None
                totals[parts[-1] if len(parts) > 4 else "?"] += sizes.get(block, 0)
        out = p.stdout.read()
    if p.returncode != 0:
        fail(f"{image} on {machine} exited {p.returncode}: {out.strip()[-300:]}")
    return totals


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0], epilog=__doc__.split("\n\n", 1)[1],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default="build", help="the host build folder (default: build)")
    ap.add_argument("--cpu", default="cortex-m3", choices=sorted(VARIANTS), help="core (default: cortex-m3)")
    ap.add_argument("--size", default=(40, 30), type=size_arg, help="working resolution WxH (default: 40x30)")
    ap.add_argument("--frames", default=20, type=bounded_int(4, 500),
                    help="N: the runs take N and 2N frames, 4..500 (default: 20; the log of 40x30 is about "
                         "4 MB a frame, read as it comes)")
    ap.add_argument("--top", default=30, type=bounded_int(1, 500), help="functions shown, 1..500 (default: 30)")
    a = ap.parse_args()

    qemu = shutil.which("qemu-system-arm")
    if not qemu:
        fail("qemu-system-arm not found (Debian: apt-get install qemu-system-arm)")
    folder, machine = VARIANTS[a.cpu]
    image = os.path.join(a.build, "cross", folder, "boards", "qemu-mps2-an385", "lumavel_qemu_bench.elf")
    gen = os.path.join(a.build, "tools", "stream", "lumavel_make_test_stream")
    for path, how in ((image, "cmake --build BUILD --target firmware_benchmark_cortex_m"),
                      (gen, "cmake --build BUILD --target lumavel_make_test_stream")):
        if not os.path.isfile(path):
            fail(f"{path}: not found (build it: {how})")
    demangle = shutil.which("c++filt")

    w, h = a.size
    with tempfile.TemporaryDirectory() as work:
        runs = []
        for n in (a.frames, 2 * a.frames):
            name = f"profile_{w}x{h}_{n}.lvs"
            r = subprocess.run([gen, os.path.join(work, name), str(w), str(h), str(n), "11"], capture_output=True,
                               text=True)
            if r.returncode != 0:
                fail(f"{gen} could not write the {n}-frame stream: {r.stderr.strip()}")
            print(f"running {a.cpu} at {w}x{h} over {n} frames ...", file=sys.stderr)
            runs.append(profile(qemu, machine, os.path.abspath(image), name, a.cpu, work))
    per_frame = {k: (runs[1][k] - runs[0][k]) / a.frames for k in set(runs[0]) | set(runs[1])}
    shown = sorted((k for k in per_frame if per_frame[k] > 0), key=lambda k: -per_frame[k])[: a.top]
    names = shown
    if demangle:
        names = subprocess.run([demangle], input="\n".join(shown), capture_output=True, text=True).stdout.split("\n")
    total = sum(per_frame.values())
    print(f"{a.cpu}, {w}x{h}: {total:.0f} instructions per extra frame of the benchmark "
          f"(columns and kernels phases counted twice)")
    for k, name in zip(shown, names):
        print(f"{per_frame[k]:9.0f}  {100 * per_frame[k] / total:5.1f} %  {name[:110]}")


if __name__ == "__main__":
    main()
