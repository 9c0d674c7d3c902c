"""What the Python examples share: the --out folder argument and the figure format."""
import argparse
import os


def output_folder(description: str) -> str:
    p = argparse.ArgumentParser(description=description)
    p.add_argument("--out", default=".", help="folder for the figures (created if needed)")
    out = p.parse_args().out
    os.makedirs(out, exist_ok=True)
    return out


def save(fig, out: str, name: str) -> None:
    """Writes name.png and name.pdf into out and says where."""
    for ext in ("png", "pdf"):
        path = os.path.join(out, f"{name}.{ext}")
        fig.savefig(path, dpi=150 if ext == "png" else None, bbox_inches="tight")
        print(path)
