/* Lab 5: a polygon drawn and a filled one on a blue background. */
#include <conio.h>
#include <graphics.h>

int main(void)
{
    int gd = DETECT, gm;
    int outline[] = {40, 300, 160, 260, 220, 380, 120, 450, 60, 400, 40, 300};
    int filled[] = {300, 60, 560, 140, 480, 300, 340, 260};
    initgraph(&gd, &gm, "");
    putpixel(5, 5, RED); /* cleared next */
    setbkcolor(BLUE);
    cleardevice();
    setcolor(LIGHTGREEN);
    drawpoly(6, outline);
    setcolor(WHITE);
    setfillstyle(SOLID_FILL, CYAN);
    fillpoly(4, filled);
    getch();
    closegraph();
    return 0;
}
