"""Video clips of trials: captions drawn onto frames, MP4 written with imageio's ffmpeg.

The frames come from :class:`creative_py.backends.pybullet.recorder.Recorder` (RGB, uint8, HxWx3);
this module knows nothing of the physics. Captions are drawn with Pillow (installed
with matplotlib) in matplotlib's DejaVu Sans, in a dark band added above the picture
(the frame is taller than the camera's picture: the caption hides nothing of it, and a
browser's video controls, drawn over the bottom of a video, do not hide the caption);
the clip is H.264 in yuv420p (what browsers play), through ``imageio-ffmpeg``::

    from creative_py.video import write_clip
    info = write_clip(path, frames, fps=5.0,
                      lines=["#2 TUL 2  hook_a2  loc 1", "tested hook_down(hook_a2)",
                             "failure: goal not reached"],
                      times=[0.0, 0.1, ...])       # simulated seconds, shown top right
    info                                           # {"frames": 37, "duration_s": 7.4, ...}
"""

from __future__ import annotations

import functools
from pathlib import Path
from typing import Sequence

import numpy as np

LINE_PX = 12
"""Caption text height in pixels (the band is one line more than the text)."""

BAND_GREY = 28
"""Grey level of the caption band (white text on it)."""


@functools.lru_cache(maxsize=4)
def _font(size: int):
    import matplotlib
    from PIL import ImageFont

    path = Path(matplotlib.get_data_path()) / "fonts" / "ttf" / "DejaVuSans.ttf"
    return ImageFont.truetype(str(path), size)


def prepare() -> None:
    """Import the encoder and load the font now (a forked clip process then inherits
    them instead of loading them once per clip)."""
    import imageio.plugins.ffmpeg  # noqa: F401
    import imageio.v2  # noqa: F401
    import imageio_ffmpeg
    from PIL import Image, ImageDraw  # noqa: F401

    imageio_ffmpeg.get_ffmpeg_exe()
    _font(LINE_PX)


def band_height(n_lines: int, line_px: int = LINE_PX) -> int:
    """Return the height (pixels) of the caption band for ``n_lines`` lines."""
    return (n_lines * (line_px + 2)) + 6 if n_lines else 0


def caption(frame: np.ndarray, lines: Sequence[str], corner: str = "",
            line_px: int = LINE_PX) -> np.ndarray:
    """Return ``frame`` with a dark band of :func:`band_height` rows added above it, in
    which ``lines`` are written (the result is that much taller than ``frame``).

    Parameters
    ----------
    frame : ndarray
        RGB image, uint8, HxWx3.
    lines : sequence of str
        Text lines, top to bottom; a line wider than the frame is cut with "...".
    corner : str
        Short text for the band's top-right corner (e.g. the simulated time).
    line_px : int
        Text size in pixels.
    """
    h, w = np.asarray(frame).shape[:2]
    return Captioner(w, h, lines, line_px)(frame, corner)


class Captioner:
    """Draws one caption above many frames of one size (the text is rasterised once).

    Parameters
    ----------
    width, height : int
        Size of the frames given, pixels (the captioned frames are :attr:`band` rows
        taller).
    lines : sequence of str
        The caption's lines (see :func:`caption`).
    line_px : int
        Text size in pixels.
    """

    def __init__(self, width: int, height: int, lines: Sequence[str],
                 line_px: int = LINE_PX) -> None:
        from PIL import Image, ImageDraw

        self.width, self.height, self.line_px = width, height, line_px
        self.font = _font(line_px)
        probe = ImageDraw.Draw(Image.new("L", (1, 1)))
        # A line wider than the frame is wrapped, never cut: the caption is the clip's
        # record of the trial (its reason, what the physics measured).
        self.lines = [part for line in lines
                      for part in _wrap(probe, line, self.font, width - 8)]
        self.band = band_height(len(self.lines), line_px)
        mask = Image.new("L", (width, max(self.band, 1)), 0)
        draw = ImageDraw.Draw(mask)
        y = 3
        for line in self.lines:
            draw.text((4, y), line, fill=255, font=self.font)
            y += line_px + 2
        self.text = np.asarray(mask, dtype=np.float32)[:self.band, :, None] / 255.0
        self._corners: dict[str, np.ndarray] = {}

    def _corner(self, text: str) -> np.ndarray:
        """Return the white-on-black RGB patch of a corner text (cached)."""
        if text not in self._corners:
            from PIL import Image, ImageDraw

            probe = ImageDraw.Draw(Image.new("L", (1, 1)))
            tw = int(probe.textlength(text, font=self.font)) + 8
            patch = Image.new("RGB", (min(tw, self.width), self.line_px + 5), (0, 0, 0))
            ImageDraw.Draw(patch).text((4, 2), text, fill=(255, 255, 255), font=self.font)
            self._corners[text] = np.asarray(patch)
        return self._corners[text]

    def __call__(self, frame: np.ndarray, corner: str = "") -> np.ndarray:
        """Return ``frame`` (RGB, uint8, the size given) with the caption band above it
        (:attr:`band` rows more) and ``corner`` at the band's (else the picture's) top
        right."""
        img = np.asarray(frame, dtype=np.uint8)
        if img.shape[:2] != (self.height, self.width):
            raise ValueError(f"caption: frame of {img.shape[1]}x{img.shape[0]} pixels, "
                             f"expected {self.width}x{self.height}")
        band = np.full((self.band, self.width, 3), BAND_GREY, np.float32)
        band = band * (1 - self.text) + 255.0 * self.text
        img = np.concatenate([band.astype(np.uint8), img], axis=0)
        if corner:
            patch = self._corner(corner)
            ph, pw = patch.shape[:2]
            img[:ph, self.width - pw:] = patch
        return img


def _wrap(draw, text: str, font, width: float) -> list[str]:
    """Return ``text`` as lines no wider than ``width`` pixels: broken between words,
    a word wider than the line broken inside it."""
    if draw.textlength(text, font=font) <= width:
        return [text]
    lines, line = [], ""
    for word in text.split(" "):
        candidate = f"{line} {word}" if line else word
        if draw.textlength(candidate, font=font) <= width:
            line = candidate
            continue
        if line:
            lines.append(line)
        line = word
        while draw.textlength(line, font=font) > width and len(line) > 1:
            cut = len(line) - 1
            while cut > 1 and draw.textlength(line[:cut], font=font) > width:
                cut -= 1
            lines.append(line[:cut])
            line = line[cut:]
    if line:
        lines.append(line)
    return lines


POSTER_SUFFIX = ".poster.jpg"
"""A clip's poster (``videos/012-create-hook_a4.poster.jpg`` beside
``videos/012-create-hook_a4.mp4``): its last frame, the scene as the trial left it when
the physics gave its verdict, captioned; what the report shows before the clip plays."""


def poster_name(clip: str) -> str:
    """Return the poster's path of a clip's path (relative or not)."""
    return clip.removesuffix(".mp4") + POSTER_SUFFIX


def write_clip(path: Path, frames: Sequence[np.ndarray], fps: float,
               lines: Sequence[str] = (), times: Sequence[float] | None = None) -> dict:
    """Caption every frame and write them as an MP4 file; return what was written.

    Parameters
    ----------
    path : Path
        The ``.mp4`` file (its folder is created).
    frames : sequence of ndarray
        RGB frames, uint8, all of one size (width and height multiples of 2).
    fps : float
        Frames per second of the clip (the recorder's rate: real time playback).
    lines : sequence of str
        The caption of every frame.
    times : sequence of float or None
        Simulated time of each frame, seconds, shown in the top-right corner.

    Returns
    -------
    dict
        ``frames``, ``duration_s``, ``width``, ``height`` (of the captioned frames: the
        caption band is above the picture), ``bytes``.
    """
    import imageio.v2 as imageio

    if not frames:
        raise ValueError(f"{path}: no frames to write")
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    h, w = frames[0].shape[:2]
    draw = Captioner(w, h, lines)
    tmp = path.with_name(f".{path.stem}.tmp.mp4")
    # x264's "veryfast" preset: a third less encoding time than the default, and no
    # bigger files at this size.
    writer = imageio.get_writer(str(tmp), fps=fps, codec="libx264", pixelformat="yuv420p",
                                macro_block_size=2, ffmpeg_log_level="error",
                                output_params=["-preset", "veryfast"])
    last = None
    try:
        for i, f in enumerate(frames):
            corner = f"t = {times[i]:.1f} s" if times is not None else ""
            last = draw(f, corner)
            writer.append_data(last)
    finally:
        writer.close()
    tmp.replace(path)
    _write_poster(Path(poster_name(str(path))), last)
    return {"frames": len(frames), "duration_s": round(len(frames) / fps, 2), "width": w,
            "height": h + draw.band, "bytes": path.stat().st_size}


def _write_poster(path: Path, frame: np.ndarray) -> None:
    """Write a clip's poster (:data:`POSTER_SUFFIX`): ``frame`` as a JPEG, atomically."""
    from PIL import Image

    tmp = path.with_name(f".{path.name}.tmp")
    Image.fromarray(frame).save(tmp, format="JPEG", quality=88)
    tmp.replace(path)
