"""TABLE.csv and run logs: what is accepted, what is refused, and the messages."""

import numpy as np
import pytest

from minseg_tui.errors import InputError
from minseg_tui.lab.saving.files import read_run_log, read_table, write_run_log, write_table
from minseg_tui.model.identify import Reading
from minseg_tui.model.runlog import RunLog

GOOD_TABLE = "u_req,u_ss,omega_ss,i_ss\n2.5,2.05,3.8,30\n3.5,3.05,5.8,34\n4.5,4.05,7.8,37\n"


def log_text(rows=None, header="t,u,omega", comments="# source: test\n"):
    if rows is None:
        rows = ["0,0,0", "0.025,0,0", "0.05,4,0", "0.075,4,3.5", "0.1,4,5.2", "0.125,4,6"]
    return comments + header + "\n" + "\n".join(rows) + "\n"


def write(tmp_path, name, text, encoding="utf-8"):
    p = tmp_path / name
    p.write_bytes(text.encode(encoding) if isinstance(text, str) else text)
    return p


def refused(reader, path):
    with pytest.raises(InputError) as exc:
        reader(path)
    msg = str(exc.value)
    assert "\n" not in msg
    return msg


# -- TABLE.csv -----------------------------------------------------------------------------


def test_table_reads_rows_with_lines(tmp_path):
    rows = read_table(write(tmp_path, "t.csv", GOOD_TABLE))
    assert rows == [
        Reading(2.5, 2.05, 3.8, 30.0, line=2),
        Reading(3.5, 3.05, 5.8, 34.0, line=3),
        Reading(4.5, 4.05, 7.8, 37.0, line=4),
    ]


def test_table_is_generous_where_unambiguous(tmp_path):
    text = "\ufeff# our group\r\n U_req , u_ss,Omega_ss ,i_ss\r\n2.5 , 2.05,3.8,30\r\n\r\n4.5,4.05,7.8,37\r\n\r\n"
    rows = read_table(write(tmp_path, "t.csv", text))
    assert [(r.u_req, r.line) for r in rows] == [(2.5, 3), (4.5, 5)]


def test_table_round_trip(tmp_path):
    rows = read_table(write(tmp_path, "t.csv", GOOD_TABLE))
    write_table(tmp_path / "u.csv", rows)
    assert read_table(tmp_path / "u.csv") == rows


@pytest.mark.parametrize(
    ("text", "where", "what"),
    [
        ("", "t.csv:", "the file is empty"),
        ("\n\n# nothing\n", "t.csv:", "the file is empty"),
        ("u_req,u_ss,omega_ss,i_ss\n", "t.csv:1:", "expected data rows"),
        ("u_req,u_ss,omega_ss\n2.5,2,3\n", "t.csv:1:", "expected a column i_ss (mA)"),
        (
            "u_req,u_ss,omega_ss,i_ss\n2.5,2.05,abc,30\n",
            "t.csv:2:",
            "expected a number for omega_ss (rad/s), got 'abc'",
        ),
        (
            "u_req,u_ss,omega_ss,i_ss\n2.5,2.05,3.8,nan\n",
            "t.csv:2:",
            "expected a number for i_ss (mA), got 'nan'",
        ),
        ("u_req,u_ss,omega_ss,i_ss\n2.5,2.05,3.8,inf\n", "t.csv:2:", "got 'inf'"),
        ("u_req,u_ss,omega_ss,i_ss\n2.5,2.05,,30\n", "t.csv:2:", "got an empty field"),
        (
            "u_req,u_ss,omega_ss,i_ss\n2.5,2.05,3.8,30\n3.5,3.05,0,34\n",
            "t.csv:3:",
            "expected omega_ss > 0",
        ),
        ("u_req,u_ss,omega_ss,i_ss\n2.5,2.05,-3.8,30\n", "t.csv:2:", "expected omega_ss > 0"),
        ("u_req,u_ss,omega_ss,i_ss\n2.5,2.05,3.8,0\n", "t.csv:2:", "expected i_ss > 0 mA"),
        ("u_req,u_ss,omega_ss,i_ss\n2.5,2,05,3.8,30\n", "t.csv:2:", "decimal comma"),
        ("u_req,u_ss,omega_ss,i_ss\n2.5,2.05,3.8\n", "t.csv:2:", "expected 4 fields"),
        (
            "u_req;u_ss;omega_ss;i_ss\n2.5;2.05;3.8;30\n3,5;3,05;5,8;34\n",
            "t.csv:3:",
            "expected one decimal mark in a file separated by semicolons",
        ),
        ("u_req,u_ss,u_ss,omega_ss,i_ss\n1,2,3,4,5\n", "t.csv:1:", "'u_ss' appears twice"),
    ],
)
def test_table_bad_input(tmp_path, text, where, what):
    msg = refused(read_table, write(tmp_path, "t.csv", text))
    assert msg.startswith(str(tmp_path / where))
    assert what in msg


def test_table_not_utf8_and_missing_file(tmp_path):
    msg = refused(
        read_table, write(tmp_path, "t.csv", b"u_req,u_ss,omega_ss,i_ss\n2.5,2\xe9,3,4\n")
    )
    assert msg.startswith(str(tmp_path / "t.csv:2:")) and "UTF-8" in msg
    msg = refused(read_table, tmp_path / "none.csv")
    assert msg.startswith(str(tmp_path / "none.csv:")) and "cannot read" in msg
    assert "directory" in refused(read_table, tmp_path)


# -- run logs -----------------------------------------------------------------------------


def test_run_log_reads_columns_metadata_and_lines(tmp_path):
    text = "# source: plant\n# ts = 0.025\nt,u,omega,u_req,count,note\n0,0,0,0,0,a\n# mid comment\n0.025,4,0,4.5,3,b\n0.05,4,2.5,4.5,10,c\n"
    log = read_run_log(write(tmp_path, "log.csv", text))
    assert log.metadata == {"source": "plant", "ts": "0.025"}
    assert log.t.tolist() == [0.0, 0.025, 0.05]
    assert log.u.tolist() == [0.0, 4.0, 4.0]
    assert log.omega.tolist() == [0.0, 0.0, 2.5]
    assert log.extra["u_req"].tolist() == [0.0, 4.5, 4.5]
    assert log.extra["count"].dtype.kind == "i" and log.extra["count"].tolist() == [0, 3, 10]
    assert log.extra["note"].tolist() == ["a", "b", "c"]
    assert log.lines.tolist() == [4, 6, 7]
    assert log.source == str(tmp_path / "log.csv")


def test_run_log_round_trip(tmp_path):
    t = np.arange(10) * 0.025 + 1e-6 * np.arange(10)
    log = RunLog(
        t=t,
        u=np.where(t > 0.1, 4.05, 0.0),
        omega=np.linspace(0, 7, 10),
        extra={
            "u_req": np.where(t > 0.1, 4.5, 0.0),
            "count": np.arange(10) * 7,
            "t_us": np.round(t * 1e6).astype(np.int64),
        },
        metadata={"source": "virtual MinSeg, seed 3"},
    )
    write_run_log(tmp_path / "out.csv", log, {"ts": "0.025"})
    back = read_run_log(tmp_path / "out.csv")
    assert back.metadata["source"] == "virtual MinSeg, seed 3" and back.metadata["ts"] == "0.025"
    assert back.columns == ["t", "u", "omega", "u_req", "count", "t_us"]
    for name in back.columns:
        np.testing.assert_allclose(back.column(name), log.column(name), rtol=1e-9)
    assert back.extra["t_us"].dtype.kind == "i"


def test_run_log_generous(tmp_path):
    text = "\ufeff# x: 1\r\n T , U ,omega\r\n0, 0 ,0\r\n\r\n0.025,4,1\r\n0.05,4,2\r\n\r\n"
    log = read_run_log(write(tmp_path, "log.csv", text))
    assert log.u.tolist() == [0.0, 4.0, 4.0] and log.lines.tolist() == [3, 5, 6]


@pytest.mark.parametrize(
    ("text", "where", "what"),
    [
        ("", "log.csv:", "expected a header row 't,u,omega', the file is empty"),
        (log_text(rows=[]), "log.csv:2:", "expected data rows"),
        (log_text(header="t,u,speed"), "log.csv:2:", "expected a column omega (rad/s)"),
        (log_text(header="time,u,omega"), "log.csv:2:", "expected a column t (s)"),
        (
            log_text(rows=["0,0,0", "0.025,x,0", "0.05,4,1"]),
            "log.csv:4:",
            "expected a number for u (V), got 'x'",
        ),
        (
            log_text(rows=["0,0,0", "0.025,4,NaN", "0.05,4,1"]),
            "log.csv:4:",
            "expected a number for omega (rad/s), got 'NaN'",
        ),
        (
            log_text(rows=["0,0,0", "0.025,4,0", "0.025,4,1"]),
            "log.csv:5:",
            "expected t (s) to increase, got 0.025 after 0.025 on line 4",
        ),
        (
            log_text(rows=["0,0,0", "0.05,4,0", "0.025,4,1"]),
            "log.csv:5:",
            "expected t (s) to increase",
        ),
        (
            log_text(rows=["0,4,0", "0.025,4,1", "0.05,4,2"]),
            "log.csv:3:",
            "expected a step in u (V)",
        ),
        (
            log_text(header="t,u,omega,u_req", rows=["0,0,0,4.5", "0.025,4,1,4.5", "0.05,4,2,4.5"]),
            "log.csv:3:",
            "expected a step in u_req (V)",
        ),
        (
            log_text(header="t,u,omega,count", rows=["0,0,0,0", "0.025,4,1,1.5.2", "0.05,4,2,3"]),
            "log.csv:4:",
            "expected a number for count (counts)",
        ),
        (log_text(rows=["0,0,0", "0.025,4,1,9", "0.05,4,2"]), "log.csv:4:", "expected 3 fields"),
        (
            log_text(
                header="t,u,omega,t_us", rows=["0,0,0,100", "0.025,4,1,25100", "0.05,4,2,25100"]
            ),
            "log.csv:5:",
            "expected t_us (us) to increase, got 25100 again",
        ),
    ],
)
def test_run_log_bad_input(tmp_path, text, where, what):
    msg = refused(read_run_log, write(tmp_path, "log.csv", text))
    assert msg.startswith(str(tmp_path / where)), msg
    assert what in msg


def test_t_us_wrapping_at_2_32_is_not_refused(tmp_path):
    # 7000 us later, then past 2^32 = 4294967296 to 24704: 296 + 24704 = 25000 us later
    rows = ["0,0,0,4294960000", "0.025,4,1,4294967000", "0.05,4,2,24704"]
    log = read_run_log(write(tmp_path, "log.csv", log_text(header="t,u,omega,t_us", rows=rows)))
    np.testing.assert_allclose(log.board_time(), [0.0, 0.007, 0.032])


def test_run_log_without_step_can_be_read_when_asked(tmp_path):
    p = write(tmp_path, "flat.csv", log_text(rows=["0,4,0", "0.025,4,1", "0.05,4,2"]))
    assert len(read_run_log(p, require_step=False)) == 3
