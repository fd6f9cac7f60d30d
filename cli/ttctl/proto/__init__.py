"""Sans-IO protocol cores: file transfer, commands, packet scheduling, the endpoint."""
