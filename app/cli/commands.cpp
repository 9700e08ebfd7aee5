// The table of `k528` subcommands. A new subcommand: write cmd_<name>.cpp with
// a run function, declare it in cli.h (or here) and add one row.

#include "cli.h"
#include "cli_texts.h"
#include "db_cli.h"
#include "program_cli.h"

namespace k528::cli {

int runPanel(std::span<const std::string> args); // cmd_panel.cpp
int runPath(std::span<const std::string> args);  // cmd_path.cpp
int runPlot(std::span<const std::string> args);  // cmd_plot.cpp
int runSetupSheet(std::span<const std::string> args); // cmd_setup_sheet.cpp
int runServe(std::span<const std::string> args); // cmd_link_forward.cpp
int runLink(std::span<const std::string> args);  // cmd_link_forward.cpp
int runExercise(std::span<const std::string> args); // cmd_exercise.cpp
int runGrade(std::span<const std::string> args);    // cmd_grade.cpp
int runShop(std::span<const std::string> args);  // cmd_shop.cpp

std::span<const Command> commands() {
    static const std::vector<Command> table = {
        {"check", "check [--json] [--number N] [--lang ru|en] [--profile NAME|PATH] [--db PATH] FILE...",
         "Validate program files: one line per diagnostic, or JSON.",
         "Options:\n"
         "  --json               print {\"files\":[{\"file\",\"programs\",\"diagnostics\"}]} (cli.md)\n"
         "  --number N           number of the program of a file without %L header (default 1)\n"
         "  --lang ru|en         language of the plain output (default ru)\n"
         "  --profile NAME|PATH  also check against a machine's constants (software limits,\n"
         "                       F УСК.АВТ., axes, discretes, nesting limit): a machine of the\n"
         "                       database, a built-in name or a machine file\n"
         "  --db PATH            the database of --profile (default $K528_DB or\n"
         "                       ~/.local/share/k528studio/k528.db; a missing one is skipped)\n"
         "FILE '-' reads standard input. Exit codes: 0 no errors (warnings allowed),\n"
         "1 errors found, 2 usage or I/O error.\n",
         runCheck},
        {"format", "format [--number N] [--lang ru|en] [--renumber [--start N] [--step K]] [--in-place | --check] FILE",
         "Print the canonical text of a program file.",
         "Options:\n"
         "  --number N    number of the program of a file without %L header (default 1)\n"
         "  --lang ru|en  language of error messages (default ru)\n"
         "  --in-place    rewrite FILE instead of printing\n"
         "  --check       print nothing; exit 1 if FILE is not in canonical form\n"
         "  --renumber    number every program's frames N<start>, N<start+step>, ... (default 1, 1),\n"
         "                every GOTO/IF target following its frame (docs/program-language.md)\n"
         "A file with syntax errors is not formatted: they are printed on stderr (exit 1).\n"
         "FILE '-' reads standard input.\n",
         runFormat},
        {"db", dbUsage(),
         "The database of machines: constants, R-parameters, programs, messages, history.",
         kDbDetails, runDb},
        {"run",
         "run [--json] [--profile NAME|PATH] [--db PATH] [--program N] [--param N=V]... [--r N=V]... [--no-home]\n"
         "           [--no-check] [--from N|L<n>:N<k> [--pass K]] [--override PCT] [--max-seconds S] [--m0-wait S]\n"
         "           [--number N] [--lang ru|en] FILE",
         "Run a program on the simulated machine, headless, and report the end state.",
         "Options:\n"
         "  --json               print the end state as JSON (cli.md)\n"
         "  --profile NAME|PATH  machine profile: a machine of the database, else built in\n"
         "                       grinder-205 or training-lathe (default), else a machine file\n"
         "  --db PATH            the database of --profile (default $K528_DB or\n"
         "                       ~/.local/share/k528studio/k528.db; a missing one is skipped)\n"
         "  --program N          program of the file to start (default: the first)\n"
         "  --param N=V          machine constant C<N> for this run (repeatable)\n"
         "  --r N=V              preset R<N> before the start (repeatable)\n"
         "  --no-home            skip the reference-point cycles (a program then needs АВТ.БЕЗ ПБТ)\n"
         "  --no-check           run the file as the controller holds it, without the rules of\n"
         "                       `k528 check`: a refused frame raises its alarm when reached\n"
         "  --from N             start before frame N of the program, with its state rebuilt by the\n"
         "                       preview (modal G, feeds, R the program wrote, R224..R231, the call\n"
         "                       stack, the M functions handed again); printed (JSON: \"from\")\n"
         "                       before the axes go there: X to its reference point, Z, then X.\n"
         "                       L<n>:N<k> names frame N<k> of subprogram L<n> (also L2:40)\n"
         "  --pass K             with --from: the K-th time the frame is reached (default 1)\n"
         "  --override PCT       feed override: 0 1 2 5 10 20 35 50 75 90 100 (default 100)\n"
         "  --max-seconds S      simulated-time limit of the program (default 3600): status timeout\n"
         "  --m0-wait S          seconds an operator waits at M00 before «Пуск» (default 0)\n"
         "  --number N           number of the program of a file without %L header (default 1)\n"
         "  --lang ru|en         language of the plain output and diagnostics (default ru)\n"
         "Exit codes: 0 completed; 1 errors in the file, an alarm or a timeout; 2 usage or I/O error.\n",
         runRun},
        {"panel", "panel [--profile NAME|PATH] [--db PATH] [--machine] [--keys \"KEY KEY ...\"] [--json] [--lang ru|en]",
         "Press keys on the K923 panel of a freshly powered-on controller and print the LCD.",
         "Options:\n"
         "  --profile NAME|PATH  machine profile: a machine of the database, else built in\n"
         "                       grinder-205 or training-lathe (default), else a machine file\n"
         "  --db PATH            the database of --profile (default $K528_DB or\n"
         "                       ~/.local/share/k528studio/k528.db; a missing one is skipped)\n"
         "  --keys \"KEY ...\"     keys in order: F1..F8 K1..K12 L1..L4 UP DOWN LEFT RIGHT MODE HELP\n"
         "                       ESC SHIFT PAR ACK INS DEL ENTER 0..9 . + - * / = % !; SHIFT+KEY;\n"
         "                       WAIT:S lets S seconds of machine time pass\n"
         "  --machine            the simulated machine of the profile (its PLC, drives and\n"
         "                       pendant) instead of the engine's ideal one; --keys then also\n"
         "                       takes PUSH:BUTTON (100 ms), HOLD:BUTTON:S, PUSH:ESTOP (latches),\n"
         "                       PULL:ESTOP; buttons DRIVES_ON START STOP RESET X+ X- Z+ Z- RAPID\n"
         "                       CHUCK; FAULT:NAME breaks, CLEAR:NAME mends the K923 or PLC:\n"
         "                       PLC_LINK («НЕТ СВЯЗИ С ПЛК»), BP_LINK («НЕТ СВЯЗИ С БП»), RAM,\n"
         "                       RESIDENT, PLC_STOP («Режим ПЛК СТОП !»)\n"
         "                       PLCMODE:N the PLC imposes mode N (1..7, F1..F7); PLCMODE:0 lets go\n"
         "  --json               print {\"lines\":[4],\"leds\":{\"green\":[K],\"red\":[K],\"override\":[L],\n"
         "                       \"shift\":bool},\"blink\":{\"row\",\"column\",\"length\"}|null}\n"
         "  --lang ru|en         language of the messages on stderr (default ru; the LCD is the panel's)\n"
         "Prints the 4 LCD lines, 20 characters each. Screens: docs/panel.md.\n",
         runPanel},
        {"path",
         "path [--json] [--profile NAME|PATH] [--db PATH] [--program N] [--param N=V]... [--r N=V]...\n"
         "           [--max-frames N] [--number N] [--lang ru|en] FILE",
         "Print the programmed toolpath: the interpreter in preview, instant axes.",
         "Options:\n"
         "  --json               print {\"program\",\"segments\",\"dwells\",\"limits\",\"warnings\",\n"
         "                       \"diagnostics\",\"alarms\",\"end\",\"frames\",\"cycle_time_s\",\n"
         "                       \"cycle_run\",\"status\"} (cli.md)\n"
         "  --profile NAME|PATH  machine profile (as for run)\n"
         "  --program N          program of the file to start (default: the first)\n"
         "  --param N=V          machine constant C<N> (repeatable)\n"
         "  --r N=V              preset R<N> before the start (repeatable)\n"
         "  --max-frames N       stop an endless program after N frames (default 1000000): status limit\n"
         "The cycle time is the program run on the simulated machine as `k528 run` runs it (servo\n"
         "acceleration, feeds, dwells, the PLC's M-function answers; an M00 continued at once),\n"
         "from «Пуск» to the end; none when that run ends in an alarm or at its time limit.\n"
         "One segment per motion frame, mm as the panel shows them (X a diameter on a diameter axis);\n"
         "a frame moving X and Z has a corner where the first axis arrives. A segment beyond the\n"
         "software limits (C46/C47, C98/C99) is marked ВНЕ ГРАНИЦ. Exit codes: 0 completed or\n"
         "limit; 1 errors in the file or an alarm; 2 usage or I/O error.\n",
         runPath},
        {"plot",
         "plot [--profile NAME|PATH] [--db PATH] [--program N] [--param N=V]... [--r N=V]...\n"
         "           [--size WxH] [--view xz|3d] [--max-frames N] --out FILE.png FILE",
         "Render the backplot of a program offscreen to a PNG.",
         "Options:\n"
         "  --out FILE.png       the image to write\n"
         "  --size WxH           pixels (default 1280x800)\n"
         "  --view xz|3d         the lathe view (Z horizontal, X vertical) or the revolved stock\n"
         "  other options as for path. The blank is the file's UCG comment (docs/backplot.md).\n"
         "Draws with k528-plot (VTK) from k528's folder. Debian's VTK needs an X server even\n"
         "offscreen: run under xvfb-run -a -s \"-screen 0 1280x800x24\". Segments beyond the\n"
         "software limits are listed on stderr as ВНЕ ГРАНИЦ.\n",
         runPlot},
        {"setup-sheet",
         "setup-sheet [--profile NAME|PATH] [--db PATH] [--param N=V]... [--r N=V]... [--blank UCG,…]\n"
         "           [--lang ru|en] [--no-cycle-times] [--json] --out FILE.pdf FILE",
         "Write the setup sheet (карта наладки) of a program file on a machine as PDF.",
         "Options:\n"
         "  --out FILE.pdf       the PDF to write (A4)\n"
         "  --profile NAME|PATH  the machine (as for run): its tools (tool.N.*), R presets, constants\n"
         "  --r N=V              preset R<N> over the machine's presets (repeatable)\n"
         "  --blank UCG,…        the blank, instead of the file's UCG comment\n"
         "  --lang ru|en         the sheet's language (default ru)\n"
         "  --no-cycle-times     leave the cycle times out (no run on the simulated machine)\n"
         "  --json               print the sheet's content as JSON (--out then optional)\n"
         "The sheet: the machine, the blank, the tools by turret station with kind, tip radius,\n"
         "orientation and offsets (from the R-parameters they name), each program with its cycle\n"
         "time (as path reports it; subprograms have none), the R-parameters to preset with their\n"
         "values in discretes and mm. Written by k528-sheet (Qt) from k528's folder; no display\n"
         "needed. Exit codes: 0 written; 1 errors in the file; 2 usage or I/O error.\n",
         runSetupSheet},
        {"exercise", "exercise list [--json] [--lang ru|en] | exercise show ID [--reference | --given] [--json] [--lang ru|en] | exercise attempts [ID] [--student NAME] [--limit N] [--json | --csv] [--db LOCATION]",
         "The training course's exercises: the list, one task, its reference program, the attempts on record.",
         "Commands:\n"
         "  list                 the exercises of the course in order (id, machine, title)\n"
         "  show ID              the task: machine, blank, drawing, limits, the operator's steps, hints\n"
         "  attempts [ID]        the graded attempts in the database (k528 grade --record), newest first\n"
         "Options:\n"
         "  --reference          print only the reference program (a program file)\n"
         "  --given              print only the program handed out with the task\n"
         "  --student NAME       attempts: only this student's\n"
         "  --limit N            attempts: the newest N\n"
         "  --db LOCATION        attempts: the database (a file or postgresql://...; default $K528_DB,\n"
         "                       else the data folder's)\n"
         "  --csv                attempts: id,at,student,exercise,file,score,passed,status,cycle_time_s,deductions\n"
         "  --json               JSON (list: an array of {id, position, machine, title, ...}; attempts:\n"
         "                       {id, at, recorded_by, host, student, exercise, file, sha256, score, passed,\n"
         "                       status, cycle_time_s, grade})\n"
         "  --lang ru|en         language of the texts (default ru)\n"
         "Exercises and their format: docs/training-course.md.\n",
         runExercise},
        {"grade", "grade ID FILE... [--json | --csv] [--geometry] [--student NAME] [--lang ru|en] [--jobs N] [--record] [--db LOCATION]",
         "Grade students' program files against an exercise: run, part, collisions, steps, score.",
         "Options:\n"
         "  --json               an array of one object per file: file, student, score, passed,\n"
         "                       status, deductions [{points, frame, line, text_ru, text_en, ...}]\n"
         "  --csv                the class's record: student,file,exercise,score,passed,status,\n"
         "                       cycle_time_s,deductions (texts in --lang), one line a file\n"
         "  --geometry           (with --json) also the blank, the finished part, the drawing\n"
         "  --student NAME       the student of one FILE (default: the file's name)\n"
         "  --lang ru|en         language of the report (default ru)\n"
         "  --jobs N             files graded at once (default: the processor count)\n"
         "  --record             keep each graded attempt in the database (student, exercise, the program,\n"
         "                       the grade, the time): k528 exercise attempts lists them, as the studio's\n"
         "                       Training dock does\n"
         "  --db LOCATION        the database of --record (implies it; default $K528_DB, else the data\n"
         "                       folder's)\n"
         "Each FILE runs on its own simulated machine as the operator would: its '; OPERATOR:'\n"
         "lines, else drives on, reference points, АВТОМАТ, «Пуск» (docs/training-course.md).\n"
         "One file: a report; several: a table. Exit codes: 0 every file passed; 1 some did not;\n"
         "2 usage or I/O error.\n",
         runGrade},
        {"serve", "serve --port DEVICE|--tcp HOST:PORT [--profile NAME|PATH] [--db PATH] [--address A] [--baud B] [--parity none|even|odd] [--keys \"KEY ...\"] [--stdin-keys] [--lang ru|en]",
         "The simulated K528-05 as a Modbus RTU server on a serial device, in real time.",
         "Options:\n"
         "  --port DEVICE        serial port or one end of a pty pair\n"
         "  --tcp HOST:PORT      Modbus TCP instead (one controller a process; --address is the unit id)\n"
         "  --address A          station address 1..247 (default 1)\n"
         "  --baud B             default 115200; --parity none|even|odd (default none); --stop-bits 1|2\n"
         "  --profile, --db      the machine, as for `k528 run`\n"
         "  --keys \"KEY ...\"     K923 keys pressed before serving (those of `k528 panel`), e.g.\n"
         "                       \"F7 DOWN DOWN ENTER\" for УПРАВЛЕНИЕ ДАННЫМИ «РАБОТА С ПЭВМ»\n"
         "  --stdin-keys         also keys read from standard input while serving, a line at a time\n"
         "  --lang ru|en         language of the messages on stderr (default ru)\n"
         "The register map: shared/spec/link.md, docs/link.md. Runs until SIGINT/SIGTERM.\n",
         runServe},
        {"link", "link --port DEVICE|--tcp HOST:PORT [--address A] [--baud B] [--parity none|even|odd] ping|status|pull|push|clear|diag|watch|scan ... | link --list",
         "The workstation's client of a K528-05 over RS485 (Modbus RTU plugin) or Modbus TCP.",
         "Lines: --port DEVICE (RS485) or --tcp HOST:PORT (a gateway; --address is the unit id).\n"
         "Commands:\n"
         "  ping                 echo and identity\n"
         "  status [--json]      the live state\n"
         "  pull --out FILE      C, R, programs and messages into a machine file\n"
         "  push FILE            a machine file (C, R, programs, messages) or a program file (its\n"
         "                       programs and %MESSAGES) into the controller, only in F7 «РАБОТА С\n"
         "                       ПЭВМ»; each part staged, committed whole and read back; a push that\n"
         "                       stops says which parts are new and which are as they were\n"
         "  clear c|r            clear the C or the R area (manual 2.6.8; F7 «РАБОТА С ПЭВМ» only)\n"
         "  diag [--json] [--clear]  the station's bus counters (Modbus function 08)\n"
         "  watch [--json] [--seconds S] [--interval-ms MS]  the live state, every 100 ms; on a lost\n"
         "                       line says since when, keeps the last values as stale, goes on by itself\n"
         "  scan [--bauds B,B...] [--addresses A-B] [--json]  the stations that answer and who they\n"
         "                       are (default: 115200 bit/s, addresses 1-247), one a line\n"
         "  --frames FILE        save the frame log (time, direction, bytes, CRC) when done\n"
         "  --list               the plugins found (and refused) and the serial ports\n"
         "  --timeout-ms MS      answer timeout (default 200)\n"
         "  --lang ru|en         language of the messages and refusals (default ru); --json is the same\n"
         "Exit codes: 0 done; 1 the controller refused, a verification failed, or the file is wrong;\n"
         "2 the line does not answer, the file cannot be read, output is lost, or usage.\n",
         runLink},
        {"shop", "shop status [--json] [--watch] | publish --mqtt mqtt://HOST[:PORT] [--db PATH] [MACHINE...]",
         "The machines of the database polled on their lines: their state, or published over MQTT.",
         "A machine's line is its setting `line` (k528 db set M01 line=tcp://10.0.0.21:502/1, or\n"
         "line=serial:/dev/ttyUSB0?baud=115200&parity=none&address=1); machines without one are left out.\n"
         "Commands:\n"
         "  status [--json]      one poll of every line at once: a line (JSON: a list of objects) each\n"
         "  status --watch [--json] [--interval-ms MS] [--seconds S]  keep polling, print each change\n"
         "  publish --mqtt mqtt://HOST[:PORT] [--interval-ms MS] [--seconds S] [--client-id ID]\n"
         "                       each machine's state retained on k528/<machine>/state, each alarm\n"
         "                       raised or cleared on k528/<machine>/alarms; the publisher on\n"
         "                       k528/_publisher/<client id>, with a last will (docs/shop.md)\n"
         "  --interval-ms MS     the poll's period (default 1000); --timeout-ms MS answer timeout (200)\n"
         "  --db PATH            the database (default $K528_DB or ~/.local/share/k528studio/k528.db)\n"
         "Exit codes: 0 done (machines offline are reported, not an error); 2 usage, the database,\n"
         "or the broker cannot be reached.\n",
         runShop},
    };
    return table;
}

int usageError(std::string_view message) {
    return usageError(message, russianCommandLine());
}

int usageError(std::string_view message, bool russian) {
    std::fprintf(stderr, "k528: %.*s\n", static_cast<int>(message.size()), message.data());
    std::fprintf(stderr, "%s\n", cliText("cli.try-help", {}, russian).c_str());
    return ExitUsage;
}

void printCommandHelp(const Command& c, std::FILE* out) {
    std::fprintf(out, "Usage: k528 %.*s\n\n%.*s\n", static_cast<int>(c.usage.size()), c.usage.data(),
                 static_cast<int>(c.summary.size()), c.summary.data());
    if (!c.details.empty())
        std::fprintf(out, "\n%.*s", static_cast<int>(c.details.size()), c.details.data());
}

} // namespace k528::cli
