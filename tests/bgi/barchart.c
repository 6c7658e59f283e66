/* Lab 4: a bar chart with labelled bars in fill styles. */
#include <conio.h>
#include <graphics.h>
#include <stdio.h>

int main(void)
{
    int gd = DETECT, gm, i;
    int marks[5] = {120, 250, 180, 300, 90};
    char label[16];
    initgraph(&gd, &gm, NULL);
    setcolor(WHITE);
    line(50, 420, 600, 420);
    line(50, 420, 50, 50);
    for (i = 0; i < 5; i++) {
        setfillstyle(i == 4 ? LINE_FILL : SOLID_FILL, i + 1);
        bar(80 + i * 100, 420 - marks[i], 140 + i * 100, 419);
        sprintf(label, "S%d", i + 1);
        outtextxy(100 + i * 100, 430, label);
    }
    outtextxy(250, 20, "MARKS");
    while (!kbhit())
        delay(100);
    closegraph();
    return 0;
}
