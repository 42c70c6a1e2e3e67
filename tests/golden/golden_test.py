#!/usr/bin/env python3
"""Golden test of one skin technique: render the built-in head with the default knobs and
compare the frame and the cost model's numbers with the files under tests/golden/data/.

Usage: golden_test.py SKINSIM DATA_DIR OUT_DIR GOLDEN [--update]
       golden_test.py SKINSIM DATA_DIR OUT_DIR --coverage

GOLDEN is a directory of DATA_DIR: a technique's name (its defaults), or TECHNIQUE@VARIANT
whose args.txt holds the knobs that differ (e.g. mobile@mediump: --skin-precision mediump).

The frame is rendered with 1, 2 and 8 host threads (SKINSIM_GOLDEN_THREADS, e.g. "2", picks
others: the sanitizer stage of scripts/test.sh renders once); each must match the golden. Set
SKINSIM_UPDATE_GOLDEN=1 (or pass --update) to rewrite the goldens after an intended change.
On a mismatch the new frame and a difference image are written to OUT_DIR/TECHNIQUE/.
"""
import json
import os
import struct
import shutil
import subprocess
import sys
import zlib

RESOLUTION = "256x192"  # small: the seven techniques together stay well under a minute
DEVICE = "ipad4"
SIGNIFICANT_DIGITS = 9  # modelled times and ratios are compared to this printed precision


def technique_of(golden):
    return golden.split("@")[0]


def variant_args(golden_dir):
    """The knobs a TECHNIQUE@VARIANT golden sets (its args.txt), none for a technique's own."""
    path = os.path.join(golden_dir, "args.txt")
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return f.read().split()


def render(skinsim, technique, args, threads, out_dir):
    # The test's own scratch directory: skinsim run replaces only directories it marked, and
    # one left by an older build (another marker) would be refused.
    shutil.rmtree(out_dir, ignore_errors=True)
    subprocess.run([skinsim, "run", "--technique", technique, "--device", DEVICE,
                    "--resolution", RESOLUTION, "--no-reference", "--threads", str(threads),
                    "--out", out_dir] + args, check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(out_dir, "result.json")) as f:
        result = json.load(f)
    numbers = {"counters": result["counters"], "timing": result["timing"]}
    with open(os.path.join(out_dir, "frame.png"), "rb") as f:
        return numbers, f.read()


# --- numbers ---------------------------------------------------------------------------

def rounded(value):
    """Floats at the printed precision; everything else unchanged."""
    if isinstance(value, float):
        return float(f"{value:.{SIGNIFICANT_DIGITS}g}")
    if isinstance(value, dict):
        return {k: rounded(v) for k, v in value.items()}
    if isinstance(value, list):
        return [rounded(v) for v in value]
    return value


def named(items, index):
    """A path element for a list entry: its name where it has one, else its index."""
    item = items[index]
    return item["name"] if isinstance(item, dict) and "name" in item else str(index)


def differences(old, new, path="", out=None):
    """Every leaf that moved, as 'path: old -> new'."""
    out = [] if out is None else out
    if isinstance(old, dict) and isinstance(new, dict):
        for key in sorted(set(old) | set(new)):
            sub = f"{path}.{key}" if path else key
            if key not in old or key not in new:
                out.append(f"{sub}: {old.get(key, '(absent)')} -> {new.get(key, '(absent)')}")
            else:
                differences(old[key], new[key], sub, out)
    elif isinstance(old, list) and isinstance(new, list) and len(old) == len(new):
        for i in range(len(old)):
            differences(old[i], new[i], f"{path}[{named(old, i)}]", out)
    elif old != new:
        out.append(f"{path}: {json.dumps(old)} -> {json.dumps(new)}")
    return out


# --- images: 8-bit RGB/RGBA PNGs, the only kind skinsim writes ---------------------------

def decode_png(data):
    """(width, height, channels, rows of bytes) of a non-interlaced 8-bit RGB(A) PNG."""
    pos, idat, width = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, color = struct.unpack(">IIBB", body[:10])
            if depth != 8 or color not in (2, 6):
                raise ValueError(f"unsupported PNG: bit depth {depth}, colour type {color}")
            channels = 3 if color == 2 else 4
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw, stride, rows = zlib.decompress(idat), width * channels, []
    previous = bytearray(stride)
    for y in range(height):
        start = y * (stride + 1)
        kind, row = raw[start], bytearray(raw[start + 1:start + 1 + stride])
        for i in range(stride):
            a = row[i - channels] if i >= channels else 0
            b = previous[i]
            c = previous[i - channels] if i >= channels else 0
            if kind == 1:
                row[i] = (row[i] + a) & 255
            elif kind == 2:
                row[i] = (row[i] + b) & 255
            elif kind == 3:
                row[i] = (row[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                row[i] = (row[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(row))
        previous = row
    return width, height, channels, rows


def encode_png(width, height, rows):
    """An 8-bit RGB PNG of the rows (filter type 0)."""
    def chunk(kind, body):
        return (struct.pack(">I", len(body)) + kind + body +
                struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF))
    raw = b"".join(b"\0" + row for row in rows)
    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)  # 8-bit RGB
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header)
            + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def compare_images(old_png, new_png, diff_path):
    """None when the pixels match, else a message; writes the difference image on a mismatch.
    The difference image shows each channel's absolute difference, scaled so that the largest
    one is white: a change of one step in a few pixels stays visible."""
    old, new = decode_png(old_png), decode_png(new_png)
    if old[:3] != new[:3]:
        return f"image size/format changed: {old[:3]} -> {new[:3]}"
    width, height, channels, _ = old
    if old[3] == new[3]:
        return None
    deltas = [bytes(abs(o[x * channels + c] - n[x * channels + c])
                    for x in range(width) for c in range(3))
              for o, n in zip(old[3], new[3])]
    differing = sum(any(row[3 * x:3 * x + 3]) for row in deltas for x in range(width))
    largest = max(max(row) for row in deltas)
    scale = 255 // largest
    with open(diff_path, "wb") as f:
        f.write(encode_png(width, height, [bytes(d * scale for d in row) for row in deltas]))
    return (f"{differing} of {width * height} pixels differ, max channel difference {largest}; "
            f"difference image scaled x{scale}")


# --- the test ---------------------------------------------------------------------------

def write_golden(golden_dir, numbers, png):
    os.makedirs(golden_dir, exist_ok=True)
    with open(os.path.join(golden_dir, "frame.png"), "wb") as f:
        f.write(png)
    with open(os.path.join(golden_dir, "counters.json"), "w") as f:
        json.dump(rounded(numbers), f, indent=1, sort_keys=True)
        f.write("\n")


def golden_thread_counts():
    text = os.environ.get("SKINSIM_GOLDEN_THREADS", "1,2,8")
    try:
        counts = [int(t) for t in text.split(",")]
    except ValueError:
        counts = []
    if not counts or min(counts) < 1:
        sys.exit(f"SKINSIM_GOLDEN_THREADS: expected thread counts like 1,2,8, got {text!r}")
    return counts


def check_technique(skinsim, data_dir, out_dir, technique, update):
    golden_dir = os.path.join(data_dir, technique)
    work_dir = os.path.join(out_dir, technique)
    args = variant_args(golden_dir)
    if "@" in technique and not args:
        print(f"golden {technique}: a variant needs {golden_dir}/args.txt with its knobs")
        return False
    renders = {threads: render(skinsim, technique_of(technique), args, threads,
                               os.path.join(work_dir, f"threads{threads}"))
               for threads in golden_thread_counts()}
    if update:
        write_golden(golden_dir, *renders[min(renders)])
        print(f"golden {technique}: updated {golden_dir}")
    try:
        with open(os.path.join(golden_dir, "counters.json")) as f:
            golden_numbers = json.load(f)
        with open(os.path.join(golden_dir, "frame.png"), "rb") as f:
            golden_png = f.read()
    except FileNotFoundError as error:
        print(f"golden {technique}: no golden ({error.filename}); create it with "
              f"SKINSIM_UPDATE_GOLDEN=1 ctest -R golden")
        return False
    ok = True
    for threads, (numbers, png) in renders.items():
        label = f"golden {technique} ({threads} thread{'s' if threads > 1 else ''})"
        moved = differences(golden_numbers, rounded(numbers))
        for line in moved:
            print(f"{label}: {line}")
        render_dir = os.path.join(work_dir, f"threads{threads}")
        image = compare_images(golden_png, png, os.path.join(render_dir, "frame_diff.png"))
        if image:
            print(f"{label}: frame: {image}; new frame {render_dir}/frame.png, "
                  f"difference {render_dir}/frame_diff.png")
        ok = ok and not moved and not image
    if ok:
        print(f"golden {technique}: frame and counters match (1 and 2 threads)")
    else:
        print(f"golden {technique}: MISMATCH. If the change is intended, regenerate with "
              f"SKINSIM_UPDATE_GOLDEN=1 ctest -R golden and review the new images")
    return ok


def check_coverage(skinsim, data_dir):
    """Every technique of the registry (`skinsim techniques --json`) has a golden, and every
    golden a technique."""
    listed = subprocess.run([skinsim, "techniques", "--json"], check=True, capture_output=True,
                            text=True).stdout
    techniques = {t["name"] for t in json.loads(listed)}
    stored = {technique_of(d) for d in os.listdir(data_dir)
              if os.path.isdir(os.path.join(data_dir, d))}
    for missing in sorted(techniques - stored):
        print(f"golden: technique '{missing}' has no golden in {data_dir}; record it with "
              f"tests/golden/golden_test.py SKINSIM {data_dir} OUT {missing} --update, "
              f"review the frame, and re-run cmake so that golden.{missing} exists")
    for stale in sorted(stored - techniques):
        print(f"golden: {data_dir}/{stale} belongs to no technique; remove it")
    return techniques == stored


def main(argv):
    if len(argv) not in (5, 6):
        sys.exit(__doc__)
    skinsim, data_dir, out_dir, what = argv[1:5]
    if what == "--coverage":
        return 0 if check_coverage(skinsim, data_dir) else 1
    update = "--update" in argv[5:] or os.environ.get("SKINSIM_UPDATE_GOLDEN") == "1"
    return 0 if check_technique(skinsim, data_dir, out_dir, what, update) else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
