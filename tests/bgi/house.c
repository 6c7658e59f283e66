/* Lab 3: a house, its parts coloured with floodfill. */
#include <conio.h>
#include <graphics.h>

int main(void)
{
    int gd = DETECT, gm;
    initgraph(&gd, &gm, "C:\\TC\\BGI");
    setcolor(WHITE);
    rectangle(200, 200, 440, 400); /* the walls */
    line(200, 200, 320, 100);      /* the roof */
    line(320, 100, 440, 200);
    rectangle(290, 300, 350, 400); /* the door */
    rectangle(230, 230, 270, 270); /* a window */
    setfillstyle(SOLID_FILL, RED);
    floodfill(320, 150, WHITE);
    setfillstyle(SOLID_FILL, YELLOW);
    floodfill(210, 350, WHITE);
    setfillstyle(SOLID_FILL, BROWN);
    floodfill(320, 350, WHITE);
    setfillstyle(HATCH_FILL, LIGHTBLUE);
    floodfill(250, 250, WHITE);
    outtextxy(280, 420, "MY HOUSE");
    getch();
    closegraph();
    return 0;
}
