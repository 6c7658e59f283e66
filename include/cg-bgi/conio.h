/* conio.h - getch and kbhit of Turbo C for BGI programs (cg/bgi.h). */
#ifndef CG_BGI_CONIO_H
#define CG_BGI_CONIO_H

#include <cg/bgi.h>

#define getch() cg_bgi_getch()
#define kbhit() cg_bgi_kbhit()

#endif
