from graphplan.cli import main

raise SystemExit(main())
