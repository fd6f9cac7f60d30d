"""The peers of `ttctl bench transfer`: the thesis file transfer (thesis.py) and MAVLink FTP
driven through pymavlink's own client (mavftp.py), sans-IO ends run by the same Simulation, over
the same channels and seeds as ttctl's own transfer (common.py: what they share)."""

from .common import BaselineRun
from .mavftp import FtpServer, MavftpClient, mavftp_defaults, mavftp_transfer, run_mavftp
from .thesis import (
                     THESIS_TIMEOUT,
                     ThesisDialect,
                     ThesisReceiver,
                     ThesisSender,
                     run_thesis,
                     thesis_dialect,
                     thesis_transfer,
                     thesis_xml,
)

__all__ = ["THESIS_TIMEOUT", "BaselineRun", "FtpServer", "MavftpClient", "ThesisDialect", "ThesisReceiver",
           "ThesisSender", "mavftp_defaults", "mavftp_transfer", "run_mavftp", "run_thesis", "thesis_dialect",
           "thesis_transfer", "thesis_xml"]
