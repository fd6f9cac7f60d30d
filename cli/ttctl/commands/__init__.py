"""The commands that talk on a link (`send-file`, `recv-file`, `link relay`): options in,
lines and exit codes out. They drive the library (proto/, link/, ends/) and print; nothing
below this folder imports it."""
