migrate tests/db/maps.cp --map RedPart --db sqlite:never-opened.db --print-sql
absent: never-opened.db
