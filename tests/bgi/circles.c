/* Lab 2: concentric circles, an arc and an ellipse (midpoint algorithms). */
#include <conio.h>
#include <graphics.h>

void main()
{
    int gd = DETECT, gm, r;
    initgraph(&gd, &gm, "");
    for (r = 20; r <= 200; r += 30) {
        setcolor(r / 30 + 1);
        circle(getmaxx() / 2, getmaxy() / 2, r);
    }
    setcolor(WHITE);
    arc(100, 100, 0, 90, 50);
    ellipse(500, 380, 0, 360, 100, 40);
    getch();
    closegraph();
}
