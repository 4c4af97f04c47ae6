"""Hostile policy files (lab.toml beside the sessions): a typo, a section, Notepad's BOM, a
FIFO or a huge file never pass silently and never hang the lab assistant or the class view."""

from __future__ import annotations

import os
import threading
from pathlib import Path

import pytest

from minseg_tui.lab.state.compare import MAX_POLICY_BYTES, Policy, read_policy


def _write(root: Path, data: bytes) -> None:
    root.mkdir(exist_ok=True)
    (root / "lab.toml").write_bytes(data)


@pytest.mark.parametrize(
    ("text", "named"),
    [
        ("answer_first = false\n", "'answer_first'"),  # a typo of the one setting
        ("[lab]\nanswers_first = false\n", "'lab'"),  # a section the program does not read
        ("answers_first = false\ncolour = 'red'\n", "'colour'"),
    ],
)
def test_a_setting_the_program_does_not_know_is_said_not_passed_over(tmp_path, text, named):
    _write(tmp_path, text.encode())
    got = read_policy(tmp_path)
    assert got.answers_first and got.file
    assert f"unknown setting {named}" in got.problem
    assert "expected only answers_first = true or false" in got.problem


def test_notepads_byte_order_mark_and_crlf_are_read(tmp_path):
    _write(tmp_path, b"\xef\xbb\xbfanswers_first = false\r\n")
    assert read_policy(tmp_path) == Policy(False, file=True)


def test_a_file_larger_than_any_policy_is_refused_with_its_limit(tmp_path):
    _write(tmp_path, b"# a comment\n" * (MAX_POLICY_BYTES // 12 + 1) + b"answers_first = false\n")
    got = read_policy(tmp_path)
    assert got.answers_first and "larger than a policy file (64 KiB)" in got.problem


def test_a_link_to_nothing_is_a_problem_not_no_file(tmp_path):
    (tmp_path / "lab.toml").symlink_to(tmp_path / "gone.toml")
    got = read_policy(tmp_path)
    assert got.answers_first and got.file
    assert "a link to a file that does not exist" in got.problem


def test_binary_is_one_plain_line(tmp_path):
    _write(tmp_path, bytes(range(128, 256)))
    assert read_policy(tmp_path).problem.endswith("cannot be read (not UTF-8 text); answers first")


def test_a_fifo_in_its_place_is_refused_not_waited_on(tmp_path):
    fifo = tmp_path / "lab.toml"
    os.mkfifo(fifo)
    got: list[Policy] = []
    reader = threading.Thread(target=lambda: got.append(read_policy(tmp_path)), daemon=True)
    reader.start()
    reader.join(timeout=60)
    if reader.is_alive():  # blocked in open(): give it a writer so the thread ends
        os.close(os.open(fifo, os.O_WRONLY | os.O_NONBLOCK))
        reader.join()
        pytest.fail("reading lab.toml waited on a FIFO")
    assert got[0].answers_first and "not a regular file" in got[0].problem
