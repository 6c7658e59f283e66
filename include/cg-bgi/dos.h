/* dos.h - delay of Turbo C for BGI programs (cg/bgi.h). */
#ifndef CG_BGI_DOS_H
#define CG_BGI_DOS_H

#include <cg/bgi.h>

#define delay(milliseconds) cg_bgi_delay(milliseconds)

#endif
