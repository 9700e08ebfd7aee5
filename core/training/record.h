// A graded attempt as the database keeps it (db::AttemptEntry, schema
// version 4): the grade's figures in columns, the whole grade as its JSON
// (gradeJson), and the deductions read back from that JSON — their text ids
// and arguments, so a stored attempt reads in either language as a fresh
// one does (docs/training-course.md, "Attempts in the database").
//
//   d.recordAttempt(training::attemptEntry(grade, programText));
//   for (const auto& a : d.attempts({.student = "Иванов"}))
//       for (const training::Deduction& x : training::storedDeductions(a)) ...
#pragma once

#include "db/database.h"
#include "training/grade.h"
#include "util/json_fwd.h"

#include <string_view>
#include <vector>

namespace k528::training {

// `g` of `programText` (its student, exercise and file are the grade's).
db::AttemptEntry attemptEntry(const Grade& g, std::string_view programText);

// The deductions of a stored attempt (points, fails, program, frame, line,
// category, text); none when its grade JSON is not one (never thrown away:
// the row's figures still stand).
std::vector<Deduction> storedDeductions(const db::AttemptEntry& a);

// The stored grade JSON as today's grade writes it: an attempt graded before
// the collision rules were the prove-out's (2026-12-06) carries the old ids
// (a deduction's "collision.rapid_into_material", a collision's
// "kind": "tool_into_chuck"); they are read as the current rule and text ids
// (proveout/rules.h: "collision.rapid-into-material", "rule":
// "tool-into-chuck"). A grade that is not JSON is returned as its string.
Json storedGradeJson(const db::AttemptEntry& a);
// The current text id of a deduction's id of an older grade (itself when current).
std::string currentTextId(std::string_view id);

} // namespace k528::training
