// SPDX-License-Identifier: Apache-2.0
// test_program's main: runs the program/format tests and the pre-flight tests in one executable
// (one Qt Test executable per area).
#include <QCoreApplication>

int runProgramTests(int argc, char** argv);
int runPreflightTests(int argc, char** argv);

int main(int argc, char** argv) {
  QCoreApplication app(argc, argv);
  int failures = runProgramTests(argc, argv);
  failures += runPreflightTests(argc, argv);
  return failures;
}
