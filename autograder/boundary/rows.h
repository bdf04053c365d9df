#pragma once
// Each side takes its own part's rows of tasks.def: CMake defines
// PT_ROWS_OF_PART_<n> as PT_KEEP for part n's verifier and worker, and the
// other parts' rows are dropped (their functions are the solution's, linked
// beside the part).
#define PT_KEEP(...) __VA_ARGS__
#define PT_DROP(...)
#ifndef PT_ROWS_OF_PART_1
#define PT_ROWS_OF_PART_1 PT_DROP
#endif
#ifndef PT_ROWS_OF_PART_2
#define PT_ROWS_OF_PART_2 PT_DROP
#endif
#ifndef PT_ROWS_OF_PART_3
#define PT_ROWS_OF_PART_3 PT_DROP
#endif
#ifndef PT_ROWS_OF_PART_4
#define PT_ROWS_OF_PART_4 PT_DROP
#endif
#ifndef PT_ROWS_OF_PART_5
#define PT_ROWS_OF_PART_5 PT_DROP
#endif
