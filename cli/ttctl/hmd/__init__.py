"""VR headset and controller pose streams: sources (OpenVR, synthetic, replay), the frame maths
(OpenVR to ROS REP-103), recordings (JSONL, CSV, ROS 2 MCAP, ROS 1 bag), streaming over the
link (TT_VR_POSE / TT_VR_CONTROLLER) and the orbit camera's maths.

Everything here speaks in `model` samples; `ttctl hmd ...` (commands/hmd_cli.py) glues them."""
