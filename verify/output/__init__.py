"""twoball.verify.output -- report files, figures and nodal fields."""
