from hybrid.cli.main import main

raise SystemExit(main(prog="python -m hybrid"))
