"""What the scripts that write one section of BENCHMARKS.md share: replacing the section between
its markers, and the machine's name."""
import os
import platform


def replace_section(path, text, begin, end):
    """Puts `text` (which starts with `begin` and ends with `end`) in place of the file's section
    between those markers, or at its end when it has none."""
    old = open(path, encoding="utf-8").read() if os.path.exists(path) else ""
    if begin in old and end in old:
        new = old[:old.index(begin)] + text + old[old.index(end) + len(end):].lstrip("\n")
    else:
        new = old.rstrip("\n") + "\n\n" + text
    with open(path, "w", encoding="utf-8") as f:
        f.write(new)


def cpu_name():
    """The processor's model name and the number of cores."""
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                return f"{line.split(':', 1)[1].strip()}, {os.cpu_count()} cores"
    except OSError:
        pass
    return f"{platform.machine()}, {os.cpu_count()} cores"
