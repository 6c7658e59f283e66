/* Lab 1: lines in every octant from the centre, in the 16 colours. */
#include <conio.h>
#include <graphics.h>

int main(void)
{
    int gd = DETECT, gm, i;
    initgraph(&gd, &gm, "C:\\TC\\BGI");
    if (graphresult() != grOk)
        return 1;
    for (i = 0; i < 16; i++) {
        setcolor(i == 0 ? WHITE : i);
        line(320, 240, 320 + (i - 8) * 35, 20 + (i % 2) * 440);
    }
    setcolor(YELLOW);
    moveto(10, 10);
    lineto(200, 60);
    lineto(30, 150);
    putpixel(600, 400, LIGHTRED);
    getch();
    closegraph();
    return 0;
}
